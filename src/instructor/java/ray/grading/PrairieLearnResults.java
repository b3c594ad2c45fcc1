package ray.grading;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * PrairieLearn's external-grader results.json (docs.prairielearn.com, "External Grading"):
 * {@code gradable}, {@code score} as a fraction in [0, 1], {@code message}, {@code output},
 * {@code images} and one entry per test with {@code name}, {@code points}, {@code max_points},
 * {@code message}, {@code output} and {@code images}. The same outcomes as Gradescope's file, so one
 * grading path serves both platforms.
 *
 * <p>Points: {@code score} is every point earned, bonus included, over the regular tests' points,
 * as Gradescope's score over its max_score, but capped at 1, because PrairieLearn takes a question's
 * score only in [0, 1]: bonus points can make up for failed regular tests, and anything above full
 * marks is lost (extra credit beyond a question's points is an assessment setting, maxBonusPoints).
 * A bonus test shows its points as its {@code max_points}, as on Gradescope, so a failed one reads
 * 0 of 1; the score's maximum stays the regular tests' points. (PrairieLearn's results panel heads
 * the tests with the sum of their points over the sum of their maxima, bonus tests included; the
 * percentage beside it is {@code score}.)
 *
 * <p>The {@code message} is the {@link ScoreSummary}: each task's points, then the bonus apart,
 * then the total, so that bonus points cannot hide a task that failed; every test counts there, as
 * PrairieLearn shows every score at once.
 *
 * <p>Visibility: PrairieLearn shows every test to the student, so a test that is not "visible" on
 * Gradescope (hidden, after the due date, after publishing) is shown as "Hidden test N" with its
 * points and no message or output, giving nothing of the test away.
 *
 * <p>Images: a failed render test's own list holds the student's render, the reference and their
 * difference as {@code {"label", "url": "data:image/png;base64,…"}} (RenderFeedback); the top-level list is empty.
 */
public final class PrairieLearnResults {
    private PrairieLearnResults() {
    }

    public static Map<String, Object> of(List<TestOutcome> outcomes, String output) {
        return of(outcomes, output, Map.of());
    }

    /** The same, with a failed render test's pictures as its images and the known mistake it is after its message. */
    static Map<String, Object> of(List<TestOutcome> outcomes, String output, Map<String, RenderFeedback.Shown> pictures) {
        List<Map<String, Object>> tests = new ArrayList<>();
        double earned = 0;
        double max = 0;
        int hidden = 0;
        for (TestOutcome t : outcomes) {
            boolean visible = "visible".equals(t.visibility());
            Map<String, Object> test = new LinkedHashMap<>();
            test.put("name", visible ? GradescopeResults.name(t) : "Hidden test " + ++hidden + (t.bonus() ? " (bonus)" : ""));
            test.put("points", t.earned());
            test.put("max_points", t.points());
            RenderFeedback.Shown shown = visible ? pictures.get(t.id()) : null;
            test.put("message", !visible ? "" : shown != null && shown.advice != null ? t.message() + "\n" + shown.advice : t.message());
            test.put("output", "");
            test.put("images", shown != null ? shown.images : List.of());
            tests.add(test);
            earned += t.earned();
            max += t.possible();
        }
        Map<String, Object> results = new LinkedHashMap<>();
        results.put("gradable", true);
        results.put("score", max > 0 ? Math.min(1, earned / max) : 0.0);
        results.put("message", ScoreSummary.of(outcomes, t -> true) + (earned > max
                ? "PrairieLearn's score stops at full marks: the bonus points above them do not count here.\n" : ""));
        results.put("output", output);
        results.put("images", List.of());
        results.put("tests", tests);
        return results;
    }

    /**
     * The grader could not grade at all (a failure of the grader, not of the student's code):
     * PrairieLearn then awards and takes nothing and does not count the attempt.
     */
    public static Map<String, Object> notGradable(String why) {
        Map<String, Object> results = new LinkedHashMap<>();
        results.put("gradable", false);
        results.put("format_errors", List.of(why));
        results.put("message", why);
        results.put("output", why);
        return results;
    }
}
