package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.assignment.Assignment;

/**
 * A submission that attacks the grading of the students' tree (course-2019-part2), graded as
 * Gradescope grades it: the real bundle, run_autograder as root, student code as
 * {@value Sandbox#USER}. Its BvhTree (src/instructorTest/adversarial/BvhTreeAttack.java.txt) returns
 * a tree made cyclic by reflection, or over large sets a chain of five million nodes, and its
 * searches forge the place of a primitive by reflection before searching honestly; its
 * BoundingBoxes is the solution's. The grade ends in time; the box tests keep every point; each
 * attacked test fails naming what happened (a node its own descendant, a message past the wire's
 * limit, an answer out of format); no process of the student user is left.
 */
public class BvhAttacksTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path CHECKOUT = Path.of(".").toAbsolutePath().normalize();
    /** A bound on hangs, not on speed: such a grade takes about 40 s on two quiet cores. */
    private static final double LOADED_MACHINE_SECONDS = 600;

    private static Assignment before;
    private static Map<String, Object> results;
    private static double seconds;

    @BeforeClass
    public static void gradeTheAttack() throws Exception {
        assumeTrue("grading isolation needs root and the user " + Sandbox.USER + " (.ci/run and setup.sh make it)",
                Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent());
        before = Assignment.current();
        Assignment.use(Assignment.preset("course-2019-part2"));
        String attack = Files.readString(CHECKOUT.resolve("src/instructorTest/adversarial/BvhTreeAttack.java.txt"), StandardCharsets.UTF_8);
        BundleGrade grade = BundleGrade.of(CHECKOUT, FOLDER.getRoot().toPath(), (file, source) -> file.endsWith("BvhTree.java") ? attack : source);
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
    public void theBoxTestsKeepTheirPoints() {
        int checked = 0;
        for (Map<String, Object> test : tests()) {
            String name = (String) test.get("name");
            if (name.contains("BoundingBoxesTest.") || name.contains("BoxHitTest.") || name.contains("BoxHitHardCasesBonusTest.")) {
                assertEquals(name + ": " + test.get("output"), ((Number) test.get("max_score")).doubleValue(),
                        ((Number) test.get("score")).doubleValue(), 1e-9);
                checked++;
            }
        }
        assertTrue("box tests graded: " + checked, checked >= 10);
    }

    @Test
    public void eachAttackedTestFailsNamingWhatHappened() {
        Map<String, String> expected = Map.of(
                "BvhBuildTest.smallSetsKeepEveryRule", "its own descendant",
                "BvhSearchTest.yourOwnTreeAgreesWithThePlainLoop", "a message of more than",
                "BvhSearchTest.closestHitAgreesWithThePlainLoop", "out of format",
                "BvhSearchTest.anyHitStopsAtTheFirstHit", "out of format");
        int found = 0;
        for (Map<String, Object> test : tests()) {
            String name = (String) test.get("name");
            for (Map.Entry<String, String> e : expected.entrySet()) {
                if (name.contains(e.getKey())) {
                    found++;
                    assertEquals(name, 0, ((Number) test.get("score")).doubleValue(), 0);
                    assertTrue(name + ": " + test.get("output"), ((String) test.get("output")).contains(e.getValue()));
                }
            }
        }
        assertEquals(expected.size(), found);
    }

    @SuppressWarnings("unchecked")
    private static List<Map<String, Object>> tests() {
        return (List<Map<String, Object>>) results.get("tests");
    }
}
