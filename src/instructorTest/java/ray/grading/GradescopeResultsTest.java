package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.Test;

/**
 * The points arithmetic of results.json and the console table on hand-made outcomes, bonus tests
 * included: a bonus test adds its points to the score when it passes, never adds to the maximum,
 * and costs nothing when it fails; its own entry shows its points as its maximum.
 */
public class GradescopeResultsTest {
    /** Task 2: regular 2 (passed) and 1 (failed), bonus 1 (passed) and 1 (failed); task 3: regular 3 and bonus 0.5, both passed; task 4: regular 4, failed. */
    static final List<TestOutcome> OUTCOMES = List.of(
            outcome("SphereTest", "hit", 2, 2, false, true),
            outcome("SphereTest", "miss", 2, 1, false, false),
            outcome("SphereHardCasesBonusTest", "farSphere", 2, 1, true, true),
            outcome("SphereHardCasesBonusTest", "tangent", 2, 1, true, false),
            outcome("TriangleTest", "hit", 3, 3, false, true),
            outcome("TriangleHardCasesBonusTest", "tiny", 3, 0.5, true, true),
            outcome("GroupTest", "closest", 4, 4, false, false));

    static TestOutcome outcome(String simpleClass, String method, int task, double points, boolean bonus, boolean passed) {
        String className = "ray.surface." + simpleClass;
        String title = Map.of(2, "Sphere", 3, "Triangle", 4, "Group").get(task);
        return new TestOutcome(className + "#" + method, className, method, task, title, points, bonus, "visible", passed,
                passed ? "" : "[Task " + task + "] it failed", 0.1);
    }

    @SuppressWarnings("unchecked")
    static Map<String, Object> test(Map<String, Object> results, int index) {
        return ((List<Map<String, Object>>) results.get("tests")).get(index);
    }

    /** The top-level keys of Gradescope's results.json specification (gradescope-autograders.readthedocs.io, "specs"). */
    static final Set<String> GRADESCOPE_KEYS = Set.of("score", "execution_time", "output", "output_format", "test_output_format",
            "test_name_format", "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard");
    /** A test's keys in the same specification. */
    static final Set<String> GRADESCOPE_TEST_KEYS = Set.of("score", "max_score", "status", "name", "name_format", "number",
            "output", "output_format", "tags", "visibility", "extra_data");

    @Test
    @SuppressWarnings("unchecked")
    public void everyKeyIsInGradescopesSpecification() {
        List<Map<String, Object>> files = List.of(GradescopeResults.of(OUTCOMES, "graded", 1.0),
                GradescopeResults.of(OUTCOMES, "graded", 1.0, Map.of(OUTCOMES.get(1).id(), "<p>page</p>")),
                GradescopeResults.of(List.of(), "The autograder could not grade this submission: why\n", 0.1));
        for (Map<String, Object> results : files) {
            assertTrue(results.keySet().toString(), GRADESCOPE_KEYS.containsAll(results.keySet()));
            for (Map<String, Object> test : (List<Map<String, Object>>) results.get("tests")) {
                assertTrue(test.keySet().toString(), GRADESCOPE_TEST_KEYS.containsAll(test.keySet()));
            }
        }
        assertFalse("no top-level max_score: Gradescope's specification has none", files.get(0).containsKey("max_score"));
    }

    @Test
    public void theMaximumGoesInExtraDataWithTheBonusOffered() {
        Map<?, ?> extra = (Map<?, ?>) GradescopeResults.of(OUTCOMES, "", 1.0).get("extra_data");
        assertEquals(10.0, (Double) extra.get("max_score"), 0);
        assertEquals(2.5, (Double) extra.get("bonus_max_score"), 0);
        assertEquals("an older file's top-level max_score still reads", 7.0, GradescopeResults.maxScore(Map.of("max_score", 7.0)), 0);
    }

    @Test
    public void theTopLevelOutputSaysItsFormat() {
        assertEquals("text", GradescopeResults.of(OUTCOMES, "", 1.0).get("output_format"));
    }

    @Test
    public void totalsCountBonusPointsInTheScoreButNotInTheMaximum() {
        Map<String, Object> results = GradescopeResults.of(OUTCOMES, "", 1.0);
        // Regular points: 2 + 1 + 3 + 4 = 10. Earned: 2 + 3 regular, 1 + 0.5 bonus = 6.5.
        assertEquals(10.0, GradescopeResults.maxScore(results), 0);
        assertEquals(6.5, (Double) results.get("score"), 0);
    }

    @Test
    public void aPassedBonusTestScoresItsPointsOutOfItsPoints() {
        Map<String, Object> passed = test(GradescopeResults.of(OUTCOMES, "", 1.0), 2);
        assertEquals("Task 2 (Sphere): SphereHardCasesBonusTest.farSphere (bonus)", passed.get("name"));
        assertEquals("2.3", passed.get("number"));
        assertEquals(1.0, (Double) passed.get("score"), 0);
        assertEquals(1.0, (Double) passed.get("max_score"), 0);
        assertEquals("passed", passed.get("status"));
        assertEquals(List.of("task2", "bonus"), passed.get("tags"));
    }

    @Test
    public void aFailedBonusTestScoresZeroOutOfItsPoints() {
        Map<String, Object> failed = test(GradescopeResults.of(OUTCOMES, "", 1.0), 3);
        assertEquals(0.0, (Double) failed.get("score"), 0);
        assertEquals(1.0, (Double) failed.get("max_score"), 0);
        assertEquals("failed", failed.get("status"));
        assertEquals("[Task 2] it failed", failed.get("output"));
    }

    @Test
    public void regularTestsKeepTheirPointsAsMaximum() {
        Map<String, Object> results = GradescopeResults.of(OUTCOMES, "", 1.0);
        Map<String, Object> failed = test(results, 1);
        assertEquals("Task 2 (Sphere): SphereTest.miss", failed.get("name"));
        assertEquals(0.0, (Double) failed.get("score"), 0);
        assertEquals(1.0, (Double) failed.get("max_score"), 0);
        assertEquals(List.of("task2"), failed.get("tags"));
        Map<String, Object> passed = test(results, 4);
        assertEquals(3.0, (Double) passed.get("score"), 0);
        assertEquals(3.0, (Double) passed.get("max_score"), 0);
    }

    @Test
    public void withoutBonusTestsTheScoreNeverExceedsTheMaximum() {
        List<TestOutcome> regular = OUTCOMES.stream().filter(t -> !t.bonus()).toList();
        Map<String, Object> results = GradescopeResults.of(regular, "", 1.0);
        assertEquals(10.0, GradescopeResults.maxScore(results), 0);
        assertEquals(5.0, (Double) results.get("score"), 0);
    }

    @Test
    public void theTableShowsBonusPointsInTheirOwnColumn() {
        List<String> lines = GradescopeResults.table(OUTCOMES).lines().toList();
        assertEquals(String.join("\n", lines), 6, lines.size());
        assertTrue(lines.get(0), lines.get(0).matches("task +tests passed +points +bonus"));
        // Regular tests passed, regular points, then bonus points earned / offered.
        assertRow(lines.get(1), "Task 2 (Sphere)", "1 / 2", "2 / 3", "1 / 2");
        assertRow(lines.get(2), "Task 3 (Triangle)", "1 / 1", "3 / 3", "0.5 / 0.5");
        assertRow(lines.get(3), "Task 4 (Group)", "0 / 1", "0 / 4", "-");
        assertRow(lines.get(4), "total", "2 / 4", "5 / 10", "1.5 / 2.5");
        assertEquals("Score: 6.5 / 10 (5 regular + 1.5 bonus)", lines.get(5));
    }

    /** A task whose tests are all extra credit counts those passed in its row, "-" for its regular points; the totals count regular tests. */
    @Test
    public void anExtraCreditTaskShowsItsBonusTestsPassed() {
        List<TestOutcome> outcomes = new java.util.ArrayList<>(OUTCOMES);
        outcomes.add(new TestOutcome("ray.shading.X#a", "ray.shading.X", "a", 5, "Cylinder", 2, true, "visible", true, "", 0.1));
        outcomes.add(new TestOutcome("ray.shading.X#b", "ray.shading.X", "b", 5, "Cylinder", 2, true, "visible", false, "[Task 5] no", 0.1));
        List<String> lines = GradescopeResults.table(outcomes).lines().toList();
        assertRow(lines.get(4), "Task 5 (Cylinder)", "1 / 2", "-", "2 / 4");
        assertRow(lines.get(5), "total", "2 / 4", "5 / 10", "3.5 / 6.5");
    }

    private static void assertRow(String line, String task, String tests, String points, String bonus) {
        String cells = line.substring(24).trim().replaceAll(" +", " ");
        assertEquals(line, task, line.substring(0, 24).trim());
        assertEquals(line, tests + " " + points + " " + bonus, cells);
    }
}
