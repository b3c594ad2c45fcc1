package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.UnaryOperator;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.assignment.Assignment;

/**
 * A submission that attacks the callbacks a student's shading may make of the judge (the course-2017
 * assignment, where the light loops and the ray's color are the students'), graded as Gradescope
 * grades it: the real bundle, run_autograder as root, student code as {@value Sandbox#USER}. The
 * light loop of Phong reaches the worker's link to the judge by reflection and asks it to shade a hit
 * outside any shadeRay (and changes its copies of the lights); Lambertian's asks for a mirror ray of
 * depth Integer.MIN_VALUE, so the judge's own mirrors would recurse without end; the ray color has a
 * hit no surface made shaded, then shades each real hit a billion levels below the camera. Every
 * other file is the solution's. The grading ends within the bound with every other task's full
 * points (an attack costs only its own task), the forged callback fails its tests by name, and no
 * process of the student user is left.
 */
public class ShadingCallbackAttacksTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path CHECKOUT = Path.of(".").toAbsolutePath().normalize();
    /** Where each attack goes: the first line of the method's body. */
    private static final String SHADE_BODY = "ShadingContext context, int depth) {\n";
    private static final String SHADE_RAY_BODY = "shadeRay(Ray ray, int depth) {\n";
    /** A bound on hangs, not on speed: such a grade takes about 75 s on two quiet cores. */
    private static final double LOADED_MACHINE_SECONDS = 600;

    private static Assignment before;
    private static Map<String, Object> results;
    private static double seconds;

    @BeforeClass
    public static void gradeTheAttack() throws Exception {
        assumeTrue("grading isolation needs root and the user " + Sandbox.USER + " (.ci/run and setup.sh make it)",
                Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent());
        before = Assignment.current();
        Assignment.use(Assignment.preset("course-2017"));
        Map<String, UnaryOperator<String>> attacks = Map.of(
                "src/main/java/ray/shading/Phong.java", at(SHADE_BODY, "ForgedShadeHitProbe"),
                "src/main/java/ray/shading/Lambertian.java", at(SHADE_BODY, "DeepMirrorProbe"),
                "src/main/java/ray/render/RayTracer.java", at(SHADE_RAY_BODY, "ForgedHitProbe"));
        BundleGrade grade = BundleGrade.of(CHECKOUT, FOLDER.getRoot().toPath(),
                (file, source) -> attacks.getOrDefault(file, UnaryOperator.identity()).apply(source));
        results = grade.results;
        seconds = grade.seconds;
    }

    @AfterClass
    public static void restoreTheAssignment() {
        if (before != null) {
            Assignment.use(before);
        }
    }

    @Test
    public void theGradeEndsInTimeAndLeavesNoStudentProcess() throws Exception {
        assertTrue(seconds + " s", seconds < LOADED_MACHINE_SECONDS);
        assertEquals(List.of(), StudentUserProcesses.livingAfter(Sandbox.USER, 10));
    }

    @Test
    public void everyOtherTaskKeepsItsPoints() {
        for (String task : List.of("Task 1 (", "Task 3 (", "Task 4 (", "Task 6 (", "Task 7 (", "Task 8 (")) {
            double score = 0;
            double max = 0;
            for (Map<String, Object> test : tests()) {
                if (((String) test.get("name")).startsWith(task)) {
                    score += ((Number) test.get("score")).doubleValue();
                    max += ((Number) test.get("max_score")).doubleValue();
                }
            }
            assertTrue(task + " has tests", max > 0);
            assertEquals(task + "'s points", max, score, 1e-9);
        }
    }

    @Test
    public void theAttackedTasksEarnNothingFromTheirAttacks() {
        for (Map<String, Object> test : tests()) {
            String name = (String) test.get("name");
            if (name.startsWith("Task 5 (")) {
                assertEquals(name, 0, ((Number) test.get("score")).doubleValue(), 0);
            }
            if (name.contains("PhongTest.")) {
                assertTrue(name + ": " + test.get("output"), ((String) test.get("output")).contains("a shading callback outside a shadeRay call"));
            }
            // The forged hit is one more shade than the ray asked for.
            if (name.contains("RayTracerTest.aHitIsShaded")) {
                assertEquals(name, "failed", test.get("status"));
            }
        }
    }

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> tests() {
        return (List<Map<String, Object>>) results.get("tests");
    }

    /** The attack in src/instructorTest/adversarial/{@code probe}.java.txt, inserted after {@code anchor}. */
    private static UnaryOperator<String> at(String anchor, String probe) {
        return source -> {
            try {
                String attack = Files.readString(CHECKOUT.resolve("src/instructorTest/adversarial/" + probe + ".java.txt"), StandardCharsets.UTF_8);
                int end = source.indexOf(anchor) + anchor.length();
                assertTrue("anchor not found: " + anchor, end >= anchor.length());
                return source.substring(0, end) + attack + source.substring(end);
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        };
    }
}
