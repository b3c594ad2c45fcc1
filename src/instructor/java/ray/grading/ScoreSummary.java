package ray.grading;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;

/**
 * The score as students read it first, on both platforms: each task's points on a line of its own,
 * then the bonus points apart, then the total and what it is made of:
 *
 * <pre>
 * Task 1 (Camera rays): 1 / 25 points
 * Task 2 (Sphere): 25 / 25 points, bonus 2 / 2 (hidden tests: 1 of 1 passed)
 * Task 6 (Cylinder): bonus 1 / 4 (extra credit; hidden tests: 0 of 1 passed)
 * Bonus: 3 / 6 points (extra credit)
 * Total: 29 / 50 points (26 regular + 3 bonus)
 * </pre>
 *
 * <p>A total that bonus points lift (151 of 150, say) can no longer hide a task that scored almost
 * nothing: the task's own line comes first. A hidden test's points count in its task's line, as they
 * count in the score students see, with only the number of hidden tests passed, never which.
 */
final class ScoreSummary {
    private ScoreSummary() {
    }

    /**
     * Gradescope shows a test's result, and the total with it, only later (after the due date, or when
     * grades are published) unless it is "visible" or "hidden" (never shown, but counted in the total
     * students see at once): the summary in its always-visible output must not count those tests yet.
     */
    static boolean shownNowOnGradescope(TestOutcome t) {
        return "visible".equals(t.visibility()) || "hidden".equals(t.visibility());
    }

    /** One task's sums. */
    private static final class Task {
        final String title;
        double points;
        double max;
        double bonus;
        double bonusMax;
        int hidden;
        int hiddenPassed;
        int notCounted;

        Task(String title) {
            this.title = title;
        }
    }

    /**
     * The summary's lines (each ended by '\n'), or "" when there are no outcomes (the grader could not grade).
     *
     * @param counted the tests whose points may be counted now; the others are only counted in number
     */
    static String of(List<TestOutcome> outcomes, Predicate<TestOutcome> counted) {
        if (outcomes.isEmpty()) {
            return "";
        }
        Map<Integer, Task> tasks = new TreeMap<>();
        for (TestOutcome t : outcomes) {
            Task task = tasks.computeIfAbsent(t.task(), k -> new Task(t.taskTitle()));
            if (!counted.test(t)) {
                task.notCounted++;
                continue;
            }
            if (t.bonus()) {
                task.bonus += t.earned();
                task.bonusMax += t.points();
            } else {
                task.points += t.earned();
                task.max += t.points();
            }
            if (!"visible".equals(t.visibility())) {
                task.hidden++;
                task.hiddenPassed += t.passed() ? 1 : 0;
            }
        }
        StringBuilder s = new StringBuilder();
        double points = 0;
        double max = 0;
        double bonus = 0;
        double bonusMax = 0;
        int notCounted = 0;
        for (Map.Entry<Integer, Task> e : tasks.entrySet()) {
            Task t = e.getValue();
            s.append("Task ").append(e.getKey()).append(" (").append(t.title).append("): ").append(line(t)).append('\n');
            points += t.points;
            max += t.max;
            bonus += t.bonus;
            bonusMax += t.bonusMax;
            notCounted += t.notCounted;
        }
        if (bonusMax > 0) {
            s.append("Bonus: ").append(fraction(bonus, bonusMax)).append(" points (extra credit)\n");
        }
        s.append("Total: ").append(fraction(points + bonus, max)).append(" points");
        if (bonusMax > 0) {
            s.append(" (").append(number(points)).append(" regular + ").append(number(bonus)).append(" bonus)");
        }
        s.append('\n');
        if (notCounted > 0) {
            s.append("Not counted above: ").append(tests(notCounted))
                    .append(" whose results are shown after the due date or when grades are published.\n");
        }
        return s.toString();
    }

    /**
     * "25 / 25 points, bonus 1 / 2 (hidden tests: 3 of 4 passed)", "bonus 1 / 4 (extra credit;
     * hidden tests: 1 of 1 passed)", "2 tests not counted yet".
     */
    private static String line(Task t) {
        StringBuilder s = new StringBuilder();
        List<String> notes = new ArrayList<>();
        boolean regular = t.max > 0 || (t.bonusMax == 0 && t.notCounted == 0);
        if (regular) {
            s.append(fraction(t.points, t.max)).append(" points");
        }
        if (t.bonusMax > 0) {
            s.append(regular ? ", " : "").append("bonus ").append(fraction(t.bonus, t.bonusMax));
            if (!regular) {
                notes.add("extra credit");
            }
        }
        if (t.hidden > 0) {
            notes.add("hidden tests: " + t.hiddenPassed + " of " + t.hidden + " passed");
        }
        if (t.notCounted > 0) {
            notes.add(tests(t.notCounted) + " not counted yet");
        }
        if (s.length() == 0) {
            // Nothing counted yet: the note is the line.
            return String.join("; ", notes);
        }
        return notes.isEmpty() ? s.toString() : s + " (" + String.join("; ", notes) + ")";
    }

    private static String fraction(double earned, double of) {
        return number(earned) + " / " + number(of);
    }

    private static String tests(int n) {
        return n + (n == 1 ? " test" : " tests");
    }

    private static String number(double x) {
        return Gradebook.number(x);
    }
}
