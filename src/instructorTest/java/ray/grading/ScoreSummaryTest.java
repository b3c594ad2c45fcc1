package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.grading.GradescopeResultsTest.OUTCOMES;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.Test;

/**
 * The score summary students read first, on both platforms: each task's points, then the bonus
 * apart, then the total, so that bonus points cannot hide a failed task.
 */
public class ScoreSummaryTest {
    private static final String SUMMARY = String.join("\n",
            "Task 2 (Sphere): 2 / 3 points, bonus 1 / 2",
            "Task 3 (Triangle): 3 / 3 points, bonus 0.5 / 0.5",
            "Task 4 (Group): 0 / 4 points",
            "Bonus: 1.5 / 2.5 points (extra credit)",
            "Total: 6.5 / 10 points (5 regular + 1.5 bonus)",
            "");

    @Test
    public void eachTaskThenTheBonusThenTheTotal() {
        assertEquals(SUMMARY, ScoreSummary.of(OUTCOMES, t -> true));
    }

    @Test
    public void aFailedTaskShowsBeforeATotalThatBonusPointsLiftAboveTheMaximum() {
        // The case that made this summary: a jittered camera scores Task 1 1 of 25, the bonus lifts the total to 26 of 25.
        TestOutcome camera = new TestOutcome("ray.camera.CameraTest#rays", "ray.camera.CameraTest", "rays", 1, "Camera rays", 25,
                false, "visible", false, "jittered", 0.1);
        TestOutcome cameraHit = new TestOutcome("ray.camera.CameraTest#center", "ray.camera.CameraTest", "center", 1, "Camera rays", 1,
                false, "visible", true, "", 0.1);
        TestOutcome bonus = new TestOutcome("ray.surface.CylinderTest#hit", "ray.surface.CylinderTest", "hit", 6, "Cylinder",
                26, true, "visible", true, "", 0.1);
        TestOutcome hiddenBonus = new TestOutcome("ray.hidden.CylinderHiddenTest#cap", "ray.hidden.CylinderHiddenTest", "cap", 6, "Cylinder",
                1, true, "hidden", false, "missed the cap", 0.1);
        String summary = ScoreSummary.of(List.of(camera, cameraHit, bonus, hiddenBonus), t -> true);
        assertEquals(String.join("\n",
                "Task 1 (Camera rays): 1 / 26 points",
                "Task 6 (Cylinder): bonus 26 / 27 (extra credit; hidden tests: 0 of 1 passed)",
                "Bonus: 26 / 27 points (extra credit)",
                "Total: 27 / 26 points (1 regular + 26 bonus)",
                ""), summary);
    }

    @Test
    public void withoutBonusTestsThereIsNoBonusLine() {
        List<TestOutcome> regular = OUTCOMES.stream().filter(t -> !t.bonus()).toList();
        assertEquals(String.join("\n",
                "Task 2 (Sphere): 2 / 3 points",
                "Task 3 (Triangle): 3 / 3 points",
                "Task 4 (Group): 0 / 4 points",
                "Total: 5 / 10 points",
                ""), ScoreSummary.of(regular, t -> true));
    }

    @Test
    public void hiddenTestsCountWithoutSayingWhichAndLaterOnesWait() {
        List<TestOutcome> outcomes = new ArrayList<>();
        for (TestOutcome t : OUTCOMES) {
            String visibility = t.task() == 2 ? "hidden" : t.task() == 4 ? "after_due_date" : "visible";
            outcomes.add(new TestOutcome(t.id(), t.className(), t.method(), t.task(), t.taskTitle(), t.points(), t.bonus(),
                    visibility, t.passed(), t.message(), t.seconds()));
        }
        assertEquals(String.join("\n",
                "Task 2 (Sphere): 2 / 3 points, bonus 1 / 2 (hidden tests: 2 of 4 passed)",
                "Task 3 (Triangle): 3 / 3 points, bonus 0.5 / 0.5",
                "Task 4 (Group): 1 test not counted yet",
                "Bonus: 1.5 / 2.5 points (extra credit)",
                "Total: 6.5 / 6 points (5 regular + 1.5 bonus)",
                "Not counted above: 1 test whose results are shown after the due date or when grades are published.",
                ""), ScoreSummary.of(outcomes, ScoreSummary::shownNowOnGradescope));
        // PrairieLearn shows every score at once: there every test counts.
        String all = ScoreSummary.of(outcomes, t -> true);
        assertTrue(all, all.contains("Task 4 (Group): 0 / 4 points (hidden tests: 0 of 1 passed)\n"));
    }

    @Test
    public void gradescopesOutputStartsWithTheSummary() {
        Map<String, Object> results = GradescopeResults.of(OUTCOMES, "Graded files: Sphere.java\n", 1.0);
        assertEquals(SUMMARY + "\nGraded files: Sphere.java\n", results.get("output"));
        assertEquals("a grader that could not grade says only why", "why\n", GradescopeResults.of(List.of(), "why\n", 1.0).get("output"));
    }

    @Test
    public void prairieLearnsMessageIsTheSummary() {
        Map<String, Object> results = PrairieLearnResults.of(OUTCOMES, "Graded files: Sphere.java\n");
        assertEquals(SUMMARY, results.get("message"));
        assertEquals("Graded files: Sphere.java\n", results.get("output"));
    }

    @Test
    public void theConsoleTableEndsWithTheScoreAndItsParts() {
        List<String> lines = GradescopeResults.table(OUTCOMES).lines().toList();
        assertEquals("Score: 6.5 / 10 (5 regular + 1.5 bonus)", lines.get(lines.size() - 1));
    }
}
