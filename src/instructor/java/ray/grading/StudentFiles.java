package ray.grading;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The files a student fills in, found by their markers: every source file under src/main/java that
 * holds a solution block ({@link SolutionMarkers}), and the task its {@code // TODO(Task N)} comment names.
 * Adding a task to the assignment needs no list to update here.
 */
public final class StudentFiles {
    private static final Pattern TASK = Pattern.compile("//\\s*TODO\\(Task (\\d+)\\)");

    private StudentFiles() {
    }

    /** Relative path (with '/' separators) → task number, sorted by path. */
    public static Map<String, Integer> in(Path projectRoot) {
        Path sources = projectRoot.resolve("src/main/java");
        Map<String, Integer> files = new TreeMap<>();
        try (Stream<Path> walk = Files.walk(sources)) {
            for (Path file : (Iterable<Path>) walk.filter(p -> p.toString().endsWith(".java"))::iterator) {
                String text = Files.readString(file, StandardCharsets.UTF_8);
                // The marker as a line of its own: code that merely mentions it (this class) is no student file.
                if (text.lines().noneMatch(line -> line.strip().equals(SolutionMarkers.BEGIN))) {
                    continue;
                }
                Matcher m = TASK.matcher(text);
                if (!m.find()) {
                    throw new IllegalStateException(file + " has a solution block but no // TODO(Task N) comment");
                }
                files.put(projectRoot.relativize(file).toString().replace('\\', '/'), Integer.parseInt(m.group(1)));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return files;
    }
}
