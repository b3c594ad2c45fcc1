package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.grading.GradescopeResultsTest.OUTCOMES;
import static ray.grading.GradescopeResultsTest.test;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.Test;
import picocli.CommandLine;

/**
 * PrairieLearn's results.json from the same hand-made outcomes as Gradescope's: the score is a
 * fraction capped at 1, bonus tests count in it but not in the maximum, and hidden tests give
 * nothing away.
 */
public class PrairieLearnResultsTest {
    /**
     * The top-level keys of PrairieLearn's external-grader results (docs.prairielearn.com, "External
     * grading", "Grading results": gradable, score, message, output, images, tests, format_errors; and
     * points and max_points, which PrairieLearn's own Python grader writes).
     */
    static final Set<String> PRAIRIELEARN_KEYS = Set.of("gradable", "score", "points", "max_points", "output", "message",
            "images", "tests", "format_errors");
    /** A test's keys in the same documentation. */
    static final Set<String> PRAIRIELEARN_TEST_KEYS = Set.of("name", "description", "points", "max_points", "message", "output",
            "images");

    @Test
    @SuppressWarnings("unchecked")
    public void everyKeyIsInPrairieLearnsFormat() {
        for (Map<String, Object> results : List.of(PrairieLearnResults.of(OUTCOMES, "graded"), PrairieLearnResults.notGradable("why"))) {
            assertTrue(results.keySet().toString(), PRAIRIELEARN_KEYS.containsAll(results.keySet()));
            for (Map<String, Object> test : (List<Map<String, Object>>) results.getOrDefault("tests", List.of())) {
                assertTrue(test.keySet().toString(), PRAIRIELEARN_TEST_KEYS.containsAll(test.keySet()));
            }
        }
    }

    @Test
    public void theScoreIsEveryPointEarnedOverTheRegularPoints() {
        Map<String, Object> results = PrairieLearnResults.of(OUTCOMES, "graded");
        // As Gradescope's: 6.5 earned (bonus included) of 10 regular points.
        assertEquals(true, results.get("gradable"));
        assertEquals(0.65, (Double) results.get("score"), 1e-12);
        assertTrue((String) results.get("message"), ((String) results.get("message")).endsWith("Total: 6.5 / 10 points (5 regular + 1.5 bonus)\n"));
        assertEquals("graded", results.get("output"));
        assertEquals(List.of(), results.get("images"));
    }

    @Test
    public void bonusPointsAboveFullMarksAreCappedAtOne() {
        // Every test passed: 10 regular and 1.5 bonus of the 2.5 offered, 11.5 of 10.
        List<TestOutcome> all = new ArrayList<>();
        for (TestOutcome t : OUTCOMES) {
            all.add(GradescopeResultsTest.outcome(t.className().substring("ray.surface.".length()), t.method(), t.task(), t.points(),
                    t.bonus(), !t.method().equals("tangent")));
        }
        Map<String, Object> results = PrairieLearnResults.of(all, "");
        assertEquals(1.0, (Double) results.get("score"), 0);
        String message = (String) results.get("message");
        assertTrue(message, message.contains("Total: 11.5 / 10 points (10 regular + 1.5 bonus)\n"
                + "PrairieLearn's score stops at full marks: the bonus points above them do not count here.\n"));
    }

    @Test
    public void testsKeepTheirNamesPointsAndMessages() {
        Map<String, Object> results = PrairieLearnResults.of(OUTCOMES, "");
        Map<String, Object> failed = test(results, 1);
        assertEquals("Task 2 (Sphere): SphereTest.miss", failed.get("name"));
        assertEquals(0.0, (Double) failed.get("points"), 0);
        assertEquals(1.0, (Double) failed.get("max_points"), 0);
        assertEquals("[Task 2] it failed", failed.get("message"));
        Map<String, Object> bonus = test(results, 2);
        assertEquals("Task 2 (Sphere): SphereHardCasesBonusTest.farSphere (bonus)", bonus.get("name"));
        assertEquals(1.0, (Double) bonus.get("points"), 0);
        assertEquals("a bonus test is out of its own points", 1.0, (Double) bonus.get("max_points"), 0);
        Map<String, Object> failedBonus = test(results, 3);
        assertEquals(0.0, (Double) failedBonus.get("points"), 0);
        assertEquals(1.0, (Double) failedBonus.get("max_points"), 0);
    }

    @Test
    public void bonusMaximaDoNotRaiseTheScoresMaximum() {
        // Only bonus tests passed: 1 + 0.5 bonus points over 10 regular ones, not over 12.5.
        List<TestOutcome> onlyBonus = new ArrayList<>();
        for (TestOutcome t : OUTCOMES) {
            onlyBonus.add(GradescopeResultsTest.outcome(t.className().substring("ray.surface.".length()), t.method(), t.task(),
                    t.points(), t.bonus(), t.bonus() && !t.method().equals("tangent")));
        }
        assertEquals(0.15, (Double) PrairieLearnResults.of(onlyBonus, "").get("score"), 1e-12);
    }

    /** OUTCOMES with task 2's tests hidden and task 4's shown after the due date (on Gradescope). */
    private static List<TestOutcome> withHiddenTests() {
        List<TestOutcome> outcomes = new ArrayList<>();
        for (TestOutcome t : OUTCOMES) {
            String visibility = t.task() == 2 ? "hidden" : t.task() == 4 ? "after_due_date" : "visible";
            outcomes.add(new TestOutcome(t.id(), t.className(), t.method(), t.task(), t.taskTitle(), t.points(), t.bonus(),
                    visibility, t.passed(), t.message(), t.seconds()));
        }
        return outcomes;
    }

    @Test
    @SuppressWarnings("unchecked")
    public void hiddenTestsShowAsOneSummaryPerTaskByDefault() {
        Map<String, Object> results = PrairieLearnResults.of(withHiddenTests(), "");
        List<Map<String, Object>> tests = (List<Map<String, Object>>) results.get("tests");
        assertEquals(tests.toString(), List.of("Task 2 (Sphere): hidden tests", "Task 2 (Sphere): hidden tests (bonus)",
                "Task 3 (Triangle): TriangleTest.hit", "Task 3 (Triangle): TriangleHardCasesBonusTest.tiny (bonus)",
                "Task 4 (Group): hidden tests"), tests.stream().map(t -> t.get("name")).toList());
        // Task 2's regular hidden tests: 2 points (passed) and 1 (failed), never saying which.
        Map<String, Object> sphere = tests.get(0);
        assertEquals(2.0, (Double) sphere.get("points"), 0);
        assertEquals(3.0, (Double) sphere.get("max_points"), 0);
        assertEquals("1 of 2 passed, 2 / 3 points. Hidden tests do not say which one failed, or why.", sphere.get("message"));
        assertEquals("", sphere.get("output"));
        assertEquals(List.of(), sphere.get("images"));
        Map<String, Object> sphereBonus = tests.get(1);
        assertEquals(1.0, (Double) sphereBonus.get("points"), 0);
        assertEquals(2.0, (Double) sphereBonus.get("max_points"), 0);
        assertEquals("1 of 2 passed, 1 / 2 points. Hidden tests do not say which one failed, or why.", sphereBonus.get("message"));
        assertEquals("0 of 1 passed, 0 / 4 points. Hidden tests do not say which one failed, or why.", tests.get(4).get("message"));
        assertTrue("no test's name or message reaches the student", !results.toString().contains("SphereTest")
                && !results.toString().contains("GroupTest") && !results.toString().contains("it failed"));
        assertEquals("the same score", 0.65, (Double) results.get("score"), 1e-12);
    }

    @Test
    public void aTaskWhoseHiddenTestsAllPassSaysSoWithoutTheNote() {
        List<TestOutcome> passed = new ArrayList<>();
        for (TestOutcome t : withHiddenTests()) {
            passed.add(new TestOutcome(t.id(), t.className(), t.method(), t.task(), t.taskTitle(), t.points(), t.bonus(),
                    t.visibility(), true, "", t.seconds()));
        }
        assertEquals("1 of 1 passed, 4 / 4 points.", test(PrairieLearnResults.of(passed, ""), 4).get("message"));
    }

    @Test
    public void withEachHiddenTestsShowOnlyANumberAndTheirPoints() {
        Map<String, Object> results = PrairieLearnResults.of(withHiddenTests(), "", PrairieLearnResults.HiddenTests.each);
        Map<String, Object> failed = test(results, 1);
        assertEquals("Hidden test 2", failed.get("name"));
        assertEquals("", failed.get("message"));
        assertEquals(1.0, (Double) failed.get("max_points"), 0);
        assertEquals("Hidden test 3 (bonus)", test(results, 2).get("name"));
        assertEquals("Task 3 (Triangle): TriangleTest.hit", test(results, 4).get("name"));
        assertEquals("Hidden test 5", test(results, 6).get("name"));
        assertEquals(0.65, (Double) results.get("score"), 1e-12);
    }

    @Test
    public void theGradersSwitchChoosesHowHiddenTestsShow() {
        Grader each = new Grader();
        new CommandLine(each).parseArgs("--project", ".", "--classpath", "", "--hidden-tests", "each");
        assertEquals(PrairieLearnResults.HiddenTests.each, each.hiddenTests);
        if (System.getenv("RAY1_HIDDEN_TESTS") == null) {
            Grader byDefault = new Grader();
            new CommandLine(byDefault).parseArgs("--project", ".", "--classpath", "");
            assertEquals(PrairieLearnResults.HiddenTests.summary, byDefault.hiddenTests);
        }
    }

    @Test
    public void aGraderThatCannotGradeCostsNoAttempt() {
        Map<String, Object> results = PrairieLearnResults.notGradable("no such folder");
        assertEquals(false, results.get("gradable"));
        assertEquals(List.of("no such folder"), results.get("format_errors"));
    }
}
