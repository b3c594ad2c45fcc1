package ray.grading;

import com.google.gson.GsonBuilder;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * Gradescope's results.json: {@code score}, {@code execution_time}, {@code output},
 * {@code output_format}, {@code visibility}, {@code stdout_visibility}, {@code extra_data} and one
 * entry per test with {@code name}, {@code number}, {@code score}, {@code max_score},
 * {@code status}, {@code output}, {@code output_format}, {@code tags} and {@code visibility}: only
 * keys of Gradescope's specification at each level. The maximum score (the regular tests' points)
 * is no top-level key there (the assignment's points are set on Gradescope), so it goes in
 * {@code extra_data} as {@code max_score}, with the bonus points offered as {@code bonus_max_score},
 * for the class gradebook ({@link GradedResult}).
 *
 * <p>The top-level output starts with the {@link ScoreSummary}: each task's points, then the bonus
 * apart, then the total, so that bonus points cannot hide a task that failed. It counts the tests
 * students see now and the "hidden" ones (in the total Gradescope shows at once), not those shown
 * after the due date or publishing.
 *
 * <p>A bonus test ({@code @Points(..., bonus = true)}) is extra credit: its entry has
 * {@code max_score} = its points and {@code score} = its points when it passed (0 when it failed),
 * a {@code "bonus"} tag and " (bonus)" after its name, so a failed bonus test reads "0 / 1" rather
 * than a puzzling "0 / 0". The top-level {@code score} is given, so Gradescope does not add up the
 * tests' maxima: it counts every point earned, bonus included, against the assignment's points (the
 * regular tests' points), so a submission can score above the maximum, which Gradescope shows as
 * extra credit, and a failed bonus test costs nothing.
 */
public final class GradescopeResults {
    private GradescopeResults() {
    }

    public static Map<String, Object> of(List<TestOutcome> outcomes, String output, double seconds) {
        return of(outcomes, output, seconds, Map.of());
    }

    /**
     * The same, with some tests' output given as HTML (a failed render test's message with its
     * pictures, {@link RenderFeedback}), by test id; those tests say {@code "output_format": "html"}.
     */
    public static Map<String, Object> of(List<TestOutcome> outcomes, String output, double seconds, Map<String, String> html) {
        List<Map<String, Object>> tests = new ArrayList<>();
        Map<Integer, Integer> numberInTask = new TreeMap<>();
        double score = 0;
        double max = 0;
        double bonusMax = 0;
        for (TestOutcome t : outcomes) {
            int n = numberInTask.merge(t.task(), 1, Integer::sum);
            Map<String, Object> test = new LinkedHashMap<>();
            test.put("name", name(t));
            test.put("number", t.task() + "." + n);
            test.put("score", t.earned());
            test.put("max_score", t.points());
            test.put("status", t.passed() ? "passed" : "failed");
            String page = html.get(t.id());
            test.put("output", page != null ? page : t.message());
            test.put("output_format", page != null ? "html" : "text");
            test.put("tags", t.bonus() ? List.of("task" + t.task(), "bonus") : List.of("task" + t.task()));
            test.put("visibility", t.visibility());
            tests.add(test);
            score += t.earned();
            max += t.possible();
            bonusMax += t.points() - t.possible();
        }
        Map<String, Object> results = new LinkedHashMap<>();
        results.put("score", score);
        results.put("execution_time", Math.round(seconds * 10) / 10.0);
        results.put("output", withSummary(ScoreSummary.of(outcomes, ScoreSummary::shownNowOnGradescope), output));
        results.put("output_format", "text");
        results.put("visibility", "visible");
        results.put("stdout_visibility", "hidden");
        Map<String, Object> extra = new LinkedHashMap<>();
        extra.put("max_score", max);
        extra.put("bonus_max_score", bonusMax);
        results.put("extra_data", extra);
        results.put("tests", tests);
        return results;
    }

    /** The score summary first, then the grader's own output after a blank line. */
    static String withSummary(String summary, String output) {
        return summary.isEmpty() ? output : output.isEmpty() ? summary : summary + "\n" + output;
    }

    /**
     * The maximum score of results as {@link #of} builds them or as read back from the file: the
     * regular tests' points, from {@code extra_data}, or from the top-level {@code max_score} that
     * files written before it moved there carry; 0 when neither is there.
     */
    static double maxScore(Map<?, ?> results) {
        Object extra = results.get("extra_data");
        Object max = extra instanceof Map<?, ?> m && m.containsKey("max_score") ? m.get("max_score") : results.get("max_score");
        return max instanceof Number n ? n.doubleValue() : 0;
    }

    /** A test's name as students see it: "Task 2 (Sphere): SphereTest.hit", " (bonus)" after a bonus test's. */
    static String name(TestOutcome t) {
        return "Task " + t.task() + " (" + t.taskTitle() + "): " + simpleName(t.className()) + "." + t.method()
                + (t.bonus() ? " (bonus)" : "");
    }

    /** Writes the JSON atomically: an autograder that is stopped never leaves half a file. */
    public static void write(Map<String, Object> results, Path file) throws IOException {
        ReadableFiles.writeAtomically(file, json(results));
    }

    /** The file's text, as {@link #write} writes it. */
    static String json(Map<String, Object> results) {
        return new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create().toJson(results) + "\n";
    }

    /**
     * The console table: one row per task with its regular tests passed and points, and the bonus
     * points earned of those offered ("-" for a task without bonus tests), the totals, then the score
     * and what it is made of: "Score: 151 / 150 (148 regular + 3 bonus)". An extra-credit task, whose
     * tests are all bonus tests, shows those passed and "-" for its regular points.
     */
    public static String table(List<TestOutcome> outcomes) {
        // Per task: regular tests passed, regular tests, points earned, points possible, bonus earned, bonus offered,
        // bonus tests passed, bonus tests.
        Map<Integer, double[]> byTask = new TreeMap<>();
        Map<Integer, String> titles = new TreeMap<>();
        for (TestOutcome t : outcomes) {
            double[] row = byTask.computeIfAbsent(t.task(), k -> new double[8]);
            if (t.bonus()) {
                row[4] += t.earned();
                row[5] += t.points();
                row[6] += t.passed() ? 1 : 0;
                row[7] += 1;
            } else {
                row[0] += t.passed() ? 1 : 0;
                row[1] += 1;
                row[2] += t.earned();
                row[3] += t.points();
            }
            titles.put(t.task(), t.taskTitle());
        }
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "%-24s %12s  %9s%6s  %8s%n", "task", "tests passed", "points", "", "bonus"));
        double[] total = new double[8];
        for (Map.Entry<Integer, double[]> e : byTask.entrySet()) {
            double[] r = e.getValue();
            s.append(row("Task " + e.getKey() + " (" + titles.get(e.getKey()) + ")", r));
            for (int k = 0; k < total.length; k++) {
                total[k] += r[k];
            }
        }
        // The totals' tests are the regular ones, beside the regular points.
        s.append(row("total", new double[] {total[0], total[1], total[2], total[3], total[4], total[5], 0, 0}));
        s.append("Score: ").append(number(total[2] + total[4])).append(" / ").append(number(total[3]));
        if (total[5] > 0) {
            s.append(" (").append(number(total[2])).append(" regular + ").append(number(total[4])).append(" bonus)");
        }
        s.append(System.lineSeparator());
        return s.toString();
    }

    /** One line of the table; trailing blanks dropped, since the bonus column is often empty. */
    private static String row(String name, double[] r) {
        String bonus = r[5] > 0 ? String.format(Locale.ROOT, "%6s / %-6s", number(r[4]), number(r[5])) : String.format("%6s", "-");
        if (r[1] == 0 && r[7] > 0) { // all extra credit
            return String.format(Locale.ROOT, "%-24s %5d / %-4d  %15s  %s", name, (int) r[6], (int) r[7], "-", bonus).stripTrailing()
                    + System.lineSeparator();
        }
        return String.format(Locale.ROOT, "%-24s %5d / %-4d  %6s / %-6s  %s", name, (int) r[0], (int) r[1], number(r[2]),
                number(r[3]), bonus).stripTrailing() + System.lineSeparator();
    }

    /** Points as people write them: "3", "2.5". */
    static String number(double x) {
        return x == Math.rint(x) ? String.valueOf((long) x) : String.format(Locale.ROOT, "%.1f", x);
    }

    private static String simpleName(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }
}
