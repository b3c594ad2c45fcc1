package ray.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Who handed in what, from the submission_metadata.yml of Gradescope's "Export Submissions": each
 * submission folder's name at the top level, with a {@code :submitters:} list of {@code :name:},
 * {@code :email:} and {@code :sid:}:
 *
 * <pre>
 * submission_123456:
 *   :submitters:
 *   - :name: Jane Doe
 *     :sid: '1234'
 *     :email: jane@example.com
 *   :score: 42.0
 * </pre>
 *
 * <p>Only those keys are read, line by line, so the rest of the file (scores, results, history, in
 * whatever YAML it uses) can never make reading fail; a full YAML library would buy nothing here.
 */
public final class GradescopeMetadata {
    private GradescopeMetadata() {
    }

    /** The file's submitters by submission folder name; empty when there is no such file. */
    public static Map<String, List<Submitter>> read(Path file) throws IOException {
        return Files.isRegularFile(file) ? parse(Files.readString(file, StandardCharsets.UTF_8)) : Map.of();
    }

    public static Map<String, List<Submitter>> parse(String yaml) {
        Map<String, List<Submitter>> bySubmission = new LinkedHashMap<>();
        List<Submitter> submitters = null;
        int listIndent = -1;
        Map<String, String> current = null;
        for (String raw : yaml.split("\r?\n")) {
            String line = stripComment(raw);
            if (line.isBlank()) {
                continue;
            }
            int indent = line.length() - line.stripLeading().length();
            String text = line.strip();
            if (indent == 0) {
                // A new submission: "submission_123456:" (the key may be quoted).
                add(submitters, current);
                current = null;
                submitters = new ArrayList<>();
                listIndent = -1;
                bySubmission.put(unquote(text.endsWith(":") ? text.substring(0, text.length() - 1) : text), submitters);
                continue;
            }
            if (submitters == null) {
                continue;
            }
            if (listIndent < 0) {
                // Only the first :submitters: of a submission: later ones (in its history) are older copies.
                if (key(text).equals("submitters") && submitters.isEmpty() && current == null) {
                    listIndent = indent;
                }
                continue;
            }
            boolean item = text.startsWith("- ") || text.equals("-");
            if (indent < listIndent || (indent == listIndent && !item)) {
                // The list has ended: the submission's other keys follow.
                add(submitters, current);
                current = null;
                listIndent = Integer.MAX_VALUE;
                continue;
            }
            if (item) {
                add(submitters, current);
                current = new LinkedHashMap<>();
                text = text.substring(1).strip();
            }
            if (current != null && text.contains(":")) {
                current.putIfAbsent(key(text), value(text));
            }
        }
        add(submitters, current);
        return bySubmission;
    }

    private static void add(List<Submitter> submitters, Map<String, String> fields) {
        if (submitters != null && fields != null) {
            submitters.add(new Submitter(fields.getOrDefault("name", ""), fields.getOrDefault("email", ""),
                    fields.getOrDefault("sid", "")));
        }
    }

    /** "name" from ":name: Jane" or "name: Jane" (Ruby symbols keep their colon in the export). */
    private static String key(String text) {
        String s = text.startsWith(":") ? text.substring(1) : text;
        int colon = s.indexOf(':');
        return colon < 0 ? s : s.substring(0, colon).strip();
    }

    private static String value(String text) {
        String s = text.startsWith(":") ? text.substring(1) : text;
        return unquote(s.substring(s.indexOf(':') + 1).strip());
    }

    private static String unquote(String s) {
        if (s.length() >= 2 && (s.charAt(0) == '\'' || s.charAt(0) == '"') && s.charAt(s.length() - 1) == s.charAt(0)) {
            String inner = s.substring(1, s.length() - 1);
            return s.charAt(0) == '\'' ? inner.replace("''", "'") : inner.replace("\\\"", "\"").replace("\\\\", "\\");
        }
        return s;
    }

    /** A comment line reads as blank; a '#' after a value is kept, as it may be part of a name. */
    private static String stripComment(String line) {
        if (line.stripLeading().startsWith("#")) {
            return "";
        }
        return line;
    }
}
