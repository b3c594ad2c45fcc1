package ray.testing;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Test;

/**
 * `gradle test -Ptask=N` picks a task's tests by class name patterns written in build.gradle
 * (testsOfTask). Every shipped test class must match exactly the patterns of the task its
 * {@link Points} names, or a task's run would miss some of its tests or run another task's.
 */
public class TaskTestsTest {
    private static final Pattern ENTRY = Pattern.compile("^\\s*'(\\d)':\\s*\\[(.*)\\]");
    private static final Pattern QUOTED = Pattern.compile("'([^']*)'");

    @Test
    public void everyShippedTestClassMatchesExactlyItsTasksPatterns() throws Exception {
        Map<Integer, List<String>> patterns = patternsOfBuildGradle();
        assertEquals("build.gradle's testsOfTask should name the tasks 1 to 6", List.of(1, 2, 3, 4, 5, 6), new ArrayList<>(patterns.keySet()));
        List<String> wrong = new ArrayList<>();
        List<String> classes = shippedTestClasses();
        for (String name : classes) {
            Points points = Class.forName(name).getAnnotation(Points.class);
            if (points == null) {
                wrong.add(name + " has no class-level @Points naming its task");
                continue;
            }
            for (Map.Entry<Integer, List<String>> task : patterns.entrySet()) {
                boolean matches = task.getValue().stream().anyMatch(p -> matches(p, name));
                if (matches != (task.getKey() == points.task().number)) {
                    wrong.add(name + (matches ? " matches" : " does not match") + " the patterns of -Ptask=" + task.getKey()
                            + " but belongs to Task " + points.task().number);
                }
            }
        }
        assertTrue(String.join("\n", wrong), wrong.isEmpty());
        assertTrue("found too few shipped test classes to check: " + classes, classes.size() >= 15);
    }

    @Test
    public void patternsAreReadTheWayGradleReadsThem() {
        assertTrue(matches("ray.surface.Sphere*", "ray.surface.SphereTexCoordsTest"));
        assertTrue(matches("ray.camera.*", "ray.camera.PerspectiveCameraTest"));
        assertTrue(!matches("ray.surface.Sphere*", "ray.endtoend.SphereRenderTest"));
        assertTrue(matches("ray.endtoend.SphereRenderTest", "ray.endtoend.SphereRenderTest"));
    }

    /** Gradle's test filter: '*' stands for any characters, everything else for itself. */
    private static boolean matches(String pattern, String className) {
        String regex = Stream.of(pattern.split("\\*", -1)).map(Pattern::quote).collect(Collectors.joining(".*"));
        return className.matches(regex);
    }

    private static Map<Integer, List<String>> patternsOfBuildGradle() throws IOException {
        Map<Integer, List<String>> patterns = new LinkedHashMap<>();
        boolean inMap = false;
        for (String line : Files.readAllLines(Path.of("build.gradle"), StandardCharsets.UTF_8)) {
            if (line.startsWith("def testsOfTask = [")) {
                inMap = true;
                continue;
            }
            if (inMap) {
                Matcher entry = ENTRY.matcher(line);
                if (!entry.find()) {
                    break;
                }
                List<String> list = new ArrayList<>();
                Matcher quoted = QUOTED.matcher(entry.group(2));
                while (quoted.find()) {
                    list.add(quoted.group(1));
                }
                patterns.put(Integer.parseInt(entry.group(1)), list);
            }
        }
        return patterns;
    }

    /** The top-level test classes under src/test/java, by name. */
    private static List<String> shippedTestClasses() throws IOException {
        Path sources = Path.of("src/test/java");
        try (Stream<Path> files = Files.walk(sources)) {
            return files.filter(p -> p.toString().endsWith("Test.java"))
                    .map(p -> sources.relativize(p).toString().replace('\\', '/').replace('/', '.').replaceAll("\\.java$", ""))
                    .sorted().collect(Collectors.toList());
        }
    }
}
