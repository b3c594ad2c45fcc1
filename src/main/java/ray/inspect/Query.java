package ray.inspect;

import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;

/** A request's query string, {@code a=1&b=2}, with the whole-number parameters the API takes. */
final class Query {
    private final Map<String, String> values;

    private Query(Map<String, String> values) {
        this.values = values;
    }

    static Query parse(String raw) {
        Map<String, String> values = new LinkedHashMap<>();
        if (raw != null && !raw.isEmpty()) {
            for (String pair : raw.split("&")) {
                int eq = pair.indexOf('=');
                String key = decode(eq < 0 ? pair : pair.substring(0, eq));
                String value = eq < 0 ? "" : decode(pair.substring(eq + 1));
                values.putIfAbsent(key, value);
            }
        }
        return new Query(values);
    }

    /** The first of {@code names} that is missing or not a whole number, described in one line; null when all are fine. */
    String problem(String... names) {
        for (String name : names) {
            String value = values.get(name);
            if (value == null) {
                return "missing " + name;
            }
            if (!value.matches("-?\\d{1,9}")) {
                return name + " must be a whole number, but was \"" + shorten(value) + "\"";
            }
        }
        return null;
    }

    /** The parameter as a number; check {@link #problem} first. */
    int integer(String name) {
        return Integer.parseInt(values.get(name));
    }

    private static String shorten(String s) {
        String printable = s.replaceAll("\\p{Cntrl}", "?");
        return printable.length() <= 40 ? printable : printable.substring(0, 40) + "…";
    }

    private static String decode(String s) {
        try {
            return URLDecoder.decode(s, StandardCharsets.UTF_8);
        } catch (IllegalArgumentException e) {
            return s;
        }
    }
}
