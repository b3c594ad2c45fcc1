package ray.grading;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
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

    /**
     * The student files a submission may leave out: those of a task whose every graded test is a
     * bonus test (extra credit, such as the cylinder), found from the tests, not from a list. A task
     * with no graded tests at all is not extra credit: its files stay required. A file left out is
     * graded as the untouched stub, which costs nothing there.
     *
     * @param files the student files, as {@link #in} finds them
     * @param tests every graded test (TestProcess.list)
     */
    public static Set<String> optional(Map<String, Integer> files, Collection<TestOutcome> tests) {
        Map<Integer, Boolean> allBonus = new TreeMap<>();
        for (TestOutcome t : tests) {
            allBonus.merge(t.task(), t.bonus(), Boolean::logicalAnd);
        }
        Set<String> optional = new TreeSet<>();
        files.forEach((path, task) -> {
            if (allBonus.getOrDefault(task, false)) {
                optional.add(path);
            }
        });
        return optional;
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
