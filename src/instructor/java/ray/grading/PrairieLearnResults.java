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
 * <p>Visibility: PrairieLearn shows every test to the student, so the tests that are not "visible"
 * on Gradescope (hidden, after the due date, after publishing) are shown, by default
 * ({@link HiddenTests#summary}), as one entry per task, "Task 2 (Sphere): hidden tests", with their
 * points and "3 of 4 passed, 6 / 8 points": students learn how their hidden tests went in each
 * task, not which test failed, so the hidden tests' cases stay the instructor's. With
 * {@link HiddenTests#each} each is shown as "Hidden test N" with its points and no message or
 * output, as before.
 *
 * <p>Images: a failed render test's own list holds the student's render, the reference and their
 * difference as {@code {"label", "url": "data:image/png;base64,…"}} (RenderFeedback); the top-level list is empty.
 */
public final class PrairieLearnResults {
    private PrairieLearnResults() {
    }

    /**
     * How the tests that are not "visible" on Gradescope show on PrairieLearn, which shows every test
     * it is given: {@code --hidden-tests} of the grader.
     */
    public enum HiddenTests {
        /**
         * One entry per task, "Task 2 (Sphere): hidden tests", with their points and how many passed,
         * never which (a task with hidden bonus tests too gets a second entry for those, marked "(bonus)").
         */
        summary,
        /** One entry per test, "Hidden test N", with its points and no message: which one failed shows. */
        each
    }

    public static Map<String, Object> of(List<TestOutcome> outcomes, String output) {
        return of(outcomes, output, Map.of(), HiddenTests.summary);
    }

    public static Map<String, Object> of(List<TestOutcome> outcomes, String output, HiddenTests hiddenTests) {
        return of(outcomes, output, Map.of(), hiddenTests);
    }

    /** The hidden tests of one task (regular or bonus) as one entry. */
    private static final class HiddenGroup {
        final Map<String, Object> entry;
        double points;
        double max;
        int passed;
        int count;

        HiddenGroup(Map<String, Object> entry) {
            this.entry = entry;
        }
    }

    /** The same, with a failed render test's pictures as its images and the known mistake it is after its message. */
    static Map<String, Object> of(List<TestOutcome> outcomes, String output, Map<String, RenderFeedback.Shown> pictures,
            HiddenTests hiddenTests) {
        List<Map<String, Object>> tests = new ArrayList<>();
        Map<String, HiddenGroup> hiddenGroups = new LinkedHashMap<>();
        double earned = 0;
        double max = 0;
        int hidden = 0;
        for (TestOutcome t : outcomes) {
            boolean visible = "visible".equals(t.visibility());
            earned += t.earned();
            max += t.possible();
            if (!visible && hiddenTests == HiddenTests.summary) {
                // Where the task's first hidden test would be; its points and counts are filled in below.
                HiddenGroup group = hiddenGroups.computeIfAbsent(t.task() + (t.bonus() ? " bonus" : ""), k -> {
                    Map<String, Object> entry = new LinkedHashMap<>();
                    entry.put("name", "Task " + t.task() + " (" + t.taskTitle() + "): hidden tests" + (t.bonus() ? " (bonus)" : ""));
                    tests.add(entry);
                    return new HiddenGroup(entry);
                });
                group.points += t.earned();
                group.max += t.points();
                group.passed += t.passed() ? 1 : 0;
                group.count++;
                continue;
            }
            Map<String, Object> test = new LinkedHashMap<>();
            test.put("name", visible ? GradescopeResults.name(t) : "Hidden test " + ++hidden + (t.bonus() ? " (bonus)" : ""));
            test.put("points", t.earned());
            test.put("max_points", t.points());
            RenderFeedback.Shown shown = visible ? pictures.get(t.id()) : null;
            test.put("message", !visible ? "" : shown != null && shown.advice != null ? t.message() + "\n" + shown.advice : t.message());
            test.put("output", "");
            test.put("images", shown != null ? shown.images : List.of());
            tests.add(test);
        }
        for (HiddenGroup g : hiddenGroups.values()) {
            g.entry.put("points", g.points);
            g.entry.put("max_points", g.max);
            g.entry.put("message", g.passed + " of " + g.count + " passed, " + GradescopeResults.number(g.points) + " / "
                    + GradescopeResults.number(g.max) + (g.max == 1 ? " point" : " points")
                    + (g.passed < g.count ? ". Hidden tests do not say which one failed, or why." : "."));
            g.entry.put("output", "");
            g.entry.put("images", List.of());
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
