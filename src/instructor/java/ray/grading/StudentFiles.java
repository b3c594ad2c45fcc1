package ray.grading;

import java.io.IOException;
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
import ray.assignment.Assignment;
import ray.assignment.Task;
import ray.assignment.TaskTable;

/**
 * The files a student fills in: those of the assignment's tasks, as the table of tasks lists them,
 * each with its task's number in the assignment.
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

    /**
     * Relative path (with '/' separators) → task number, sorted by path: the files of every task the
     * assignment chooses, as the table of tasks lists them (none for a tree that holds none of them). Each must hold a solution block
     * ({@link SolutionMarkers}) and its task's {@code // TODO(Task N)} comment, or the tree is no
     * instructor's tree of this assignment.
     */
    public static Map<String, Integer> in(Path projectRoot) {
        Assignment assignment = Assignment.current();
        Map<String, Integer> files = new TreeMap<>();
        // A tree without any of them (a test's small project of other classes) has no student files;
        // one with only some of them is no tree of this assignment, and says which file it lacks.
        if (assignment.tasks().stream().flatMap(t -> t.projectFiles().stream()).noneMatch(f -> Files.isRegularFile(projectRoot.resolve(f)))) {
            return files;
        }
        for (Task task : assignment.tasks()) {
            int number = assignment.number(task.id());
            for (String path : task.projectFiles()) {
                Path file = projectRoot.resolve(path);
                String text;
                try {
                    text = Files.readString(file, StandardCharsets.UTF_8);
                } catch (IOException e) {
                    throw new IllegalStateException(path + ", a file of the task " + task.id() + " in " + TaskTable.PROJECT_FILE
                            + ", cannot be read: " + e.getMessage());
                }
                // The marker as a line of its own: code that merely mentions it is no student file.
                if (text.lines().noneMatch(line -> line.strip().equals(SolutionMarkers.BEGIN))) {
                    throw new IllegalStateException(path + ", a file of the task " + task.id() + ", has no solution block");
                }
                Matcher m = TASK.matcher(text);
                if (!m.find()) {
                    throw new IllegalStateException(path + " has a solution block but no // TODO(Task N) comment");
                }
                files.put(path, number);
            }
        }
        return files;
    }
}
