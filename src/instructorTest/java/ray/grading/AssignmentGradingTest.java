package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.google.gson.Gson;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;
import ray.assignment.Assignment;

/**
 * The grader grades the assignment it is asked for: its tasks only, under its numbers and titles,
 * with its extra credit. The solution gets full marks and the handout's stubs of the chosen tasks
 * nothing, in the preset's numbering and in an assignment of two tasks in an order of its own; and
 * the process's assignment is what it was before.
 */
public class AssignmentGradingTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> grade(String name, String... options) throws Exception {
        Path out = FOLDER.getRoot().toPath().resolve(name);
        List<String> args = new java.util.ArrayList<>(List.of("--project", PROJECT.toString(), "--classpath", LIBRARIES, "--out", out.toString()));
        args.addAll(List.of(options));
        Assignment before = Assignment.current();
        assertEquals(0, new CommandLine(new Grader()).execute(args.toArray(new String[0])));
        assertEquals("the grade leaves the process's assignment as it was", before, Assignment.current());
        Map<String, Object> results = new Gson().fromJson(Files.readString(out.resolve("results.json"), StandardCharsets.UTF_8), Map.class);
        return (List<Map<String, Object>>) results.get("tests");
    }

    /** Task number → its title as the entries name it ("Task 2 (Group): …"). */
    private static Map<Integer, String> titles(List<Map<String, Object>> tests) {
        Map<Integer, String> titles = new TreeMap<>();
        for (Map<String, Object> t : tests) {
            int task = Integer.parseInt(((String) t.get("number")).split("\\.")[0]);
            String name = (String) t.get("name");
            titles.put(task, name.substring(name.indexOf('(') + 1, name.indexOf(')')));
        }
        return titles;
    }

    private static double regular(List<Map<String, Object>> tests, String key) {
        return tests.stream().filter(t -> !((List<?>) t.get("tags")).contains("bonus")).mapToDouble(t -> (Double) t.get(key)).sum();
    }

    @Test(timeout = 1_800_000)
    public void theCourse2017PresetGradesItsTasksUnderItsNumbers() throws Exception {
        List<Map<String, Object>> tests = grade("course-2017", "--assignment", "course-2017");
        assertEquals(Map.of(1, "Camera rays", 2, "Ray color", 3, "Group", 4, "Sphere", 5, "Lighting", 6, "Triangle", 7, "Textures",
                8, "Cylinder"), titles(tests));
        assertTrue(regular(tests, "max_score") > 100);
        assertEquals("the solution gets every regular point", regular(tests, "max_score"), regular(tests, "score"), 0);
        assertTrue("the cylinder's tests are extra credit", tests.stream().filter(t -> ((String) t.get("number")).startsWith("8."))
                .allMatch(t -> ((List<?>) t.get("tags")).contains("bonus")));
    }

    @Test(timeout = 1_800_000)
    public void twoTasksInAnOrderOfTheirOwnAndTheirStubsScoreNothing() throws Exception {
        // The handout's stubs of the two chosen files, handed in as a student would.
        Path submission = FOLDER.getRoot().toPath().resolve("stubs");
        for (String file : List.of("src/main/java/ray/surface/Group.java", "src/main/java/ray/surface/Sphere.java")) {
            Path copy = submission.resolve(file);
            Files.createDirectories(copy.getParent());
            Files.writeString(copy, SolutionMarkers.studentVersion(Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8), file),
                    StandardCharsets.UTF_8);
        }
        List<Map<String, Object>> stubs = grade("two-stubs", "--tasks", "group, sphere", "--submission", submission.toString());
        assertEquals(Map.of(1, "Group", 2, "Sphere"), titles(stubs));
        assertTrue(regular(stubs, "max_score") > 20);
        assertEquals("the stubs get no point", 0, regular(stubs, "score"), 0);
        assertEquals(0, stubs.stream().mapToDouble(t -> (Double) t.get("score")).sum(), 0);

        List<Map<String, Object>> solution = grade("two-solution", "--tasks", "group, sphere");
        assertEquals(Map.of(1, "Group", 2, "Sphere"), titles(solution));
        assertEquals(regular(stubs, "max_score"), regular(solution, "max_score"), 0);
        assertEquals("the solution gets every regular point", regular(solution, "max_score"), regular(solution, "score"), 0);
    }

    @Test
    public void aBadAssignmentIsOneLineAndNoGrade() throws Exception {
        Path out = FOLDER.getRoot().toPath().resolve("bad");
        java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
        java.io.PrintStream before = System.err;
        int status;
        System.setErr(new java.io.PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            status = new CommandLine(new Grader()).execute("--project", PROJECT.toString(), "--classpath", LIBRARIES, "--out", out.toString(),
                    "--tasks", "sphere, kdtree");
        } finally {
            System.setErr(before);
        }
        assertEquals(1, status);
        assertTrue(err.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8).contains(
                "there is no task \"kdtree\"; the tasks are camera-rays, ray-color, group, sphere, lighting, brdfs, reflection, triangle, textures, microfacet, cylinder, bvh"));
    }
}
