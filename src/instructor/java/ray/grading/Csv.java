package ray.grading;

import java.util.List;
import java.util.stream.Collectors;

/** CSV as RFC 4180 writes it, so spreadsheets read names with commas, quotes or line breaks intact. */
public final class Csv {
    private Csv() {
    }

    /** One record, its fields quoted only when they need it, ended by CRLF. */
    public static String row(List<String> fields) {
        return fields.stream().map(Csv::field).collect(Collectors.joining(",")) + "\r\n";
    }

    public static String field(String s) {
        if (s.contains(",") || s.contains("\"") || s.contains("\n") || s.contains("\r")) {
            return '"' + s.replace("\"", "\"\"") + '"';
        }
        return s;
    }
}
