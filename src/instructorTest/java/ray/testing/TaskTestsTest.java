package ray.testing;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Test;
import ray.assignment.Task;
import ray.assignment.TaskTable;

/**
 * A graded test counts toward the task whose test patterns in the table of tasks match its class,
 * and `gradle test -Ptask=N` runs the classes those patterns match: so every graded test class must
 * match exactly one task's patterns, and every class a task's patterns match must be graded, or a
 * task would count a test of another or miss one of its own.
 */
public class TaskTestsTest {
    @Test
    public void everyGradedTestClassMatchesExactlyOneTasksPatterns() throws Exception {
        List<String> wrong = new ArrayList<>();
        List<String> classes = testClasses();
        int graded = 0;
        for (String name : classes) {
            boolean hasPoints = hasPoints(Class.forName(name));
            List<String> owners = TaskTable.standard().all().stream().filter(t -> t.hasTestClass(name)).map(Task::id)
                    .collect(Collectors.toList());
            if (hasPoints && owners.size() != 1) {
                wrong.add(name + " is graded but matches the test patterns of " + (owners.isEmpty() ? "no task" : String.join(" and ", owners)));
            }
            if (!hasPoints && !owners.isEmpty() && shipped(name)) {
                wrong.add(name + " matches the test patterns of " + owners + " but has no @Points: a task's run would run an ungraded class");
            }
            graded += hasPoints ? 1 : 0;
        }
        assertTrue(String.join("\n", wrong), wrong.isEmpty());
        assertTrue("found too few graded test classes to check: " + classes, graded >= 20);
    }

    /** Every task of the table has graded tests, and a render test when it has scenes. */
    @Test
    public void everyTaskHasTests() throws Exception {
        for (Task task : TaskTable.standard().all()) {
            List<String> own = testClasses().stream().filter(task::hasTestClass).collect(Collectors.toList());
            assertTrue(task.id() + " has no test classes", !own.isEmpty());
            if (!task.scenes().isEmpty()) {
                assertTrue(task.id() + " has scenes but no render test: " + own, own.stream().anyMatch(c -> c.startsWith("ray.endtoend.")));
            }
        }
    }

    @Test
    public void patternsAreReadTheWayGradleReadsThem() {
        Task sphere = TaskTable.standard().get("sphere");
        assertTrue(sphere.hasTestClass("ray.surface.SphereTexCoordsTest"));
        assertTrue(sphere.hasTestClass("ray.endtoend.SphereRenderTest"));
        assertTrue(!sphere.hasTestClass("ray.endtoend.SphereRenderTestX"));
        assertTrue(!sphere.hasTestClass("ray.surface.TriangleTest"));
        assertEquals("sphere", TaskTable.standard().ofTestClass("ray.hidden.SphereHiddenTest").orElseThrow().id());
    }

    /** Whether the class ships to students (the instructor's own ungraded tests may share a task's patterns). */
    private static boolean shipped(String className) {
        return Files.isRegularFile(Path.of("src/test/java", className.replace('.', '/') + ".java"));
    }

    /** A class's own @Points, or one on any of its methods. */
    private static boolean hasPoints(Class<?> type) {
        return type.getAnnotation(Points.class) != null
                || Stream.of(type.getMethods()).anyMatch(m -> m.getAnnotation(Points.class) != null);
    }

    /** The top-level test classes (*Test) under src/test/java and the instructor's tests, by name. */
    private static List<String> testClasses() throws IOException {
        List<String> names = new ArrayList<>();
        for (String folder : List.of("src/test/java", "src/instructorTest/java")) {
            Path sources = Path.of(folder);
            try (Stream<Path> files = Files.walk(sources)) {
                files.filter(p -> p.toString().endsWith("Test.java"))
                        .map(p -> sources.relativize(p).toString().replace('\\', '/').replace('/', '.').replaceAll("\\.java$", ""))
                        .forEach(names::add);
            }
        }
        names.sort(null);
        return names;
    }
}
