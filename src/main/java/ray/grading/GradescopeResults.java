package ray.grading;

import com.google.gson.GsonBuilder;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * Gradescope's results.json: {@code score}, {@code max_score}, {@code execution_time},
 * {@code output}, {@code visibility}, {@code stdout_visibility} and one entry per test with
 * {@code name}, {@code number}, {@code score}, {@code max_score}, {@code status}, {@code output},
 * {@code tags} and {@code visibility}.
 */
public final class GradescopeResults {
    private GradescopeResults() {
    }

    public static Map<String, Object> of(List<TestOutcome> outcomes, String output, double seconds) {
        List<Map<String, Object>> tests = new ArrayList<>();
        Map<Integer, Integer> numberInTask = new TreeMap<>();
        double score = 0;
        double max = 0;
        for (TestOutcome t : outcomes) {
            int n = numberInTask.merge(t.task(), 1, Integer::sum);
            Map<String, Object> test = new LinkedHashMap<>();
            test.put("name", "Task " + t.task() + " (" + t.taskTitle() + "): " + simpleName(t.className()) + "." + t.method());
            test.put("number", t.task() + "." + n);
            test.put("score", t.passed() ? t.points() : 0.0);
            test.put("max_score", t.points());
            test.put("status", t.passed() ? "passed" : "failed");
            test.put("output", t.message());
            test.put("tags", List.of("task" + t.task()));
            test.put("visibility", t.visibility());
            tests.add(test);
            score += t.passed() ? t.points() : 0;
            max += t.points();
        }
        Map<String, Object> results = new LinkedHashMap<>();
        results.put("score", score);
        results.put("max_score", max);
        results.put("execution_time", Math.round(seconds * 10) / 10.0);
        results.put("output", output);
        results.put("visibility", "visible");
        results.put("stdout_visibility", "hidden");
        results.put("tests", tests);
        return results;
    }

    /** Writes the JSON atomically: an autograder that is stopped never leaves half a file. */
    public static void write(Map<String, Object> results, Path file) throws IOException {
        String json = new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create().toJson(results);
        Path folder = file.toAbsolutePath().getParent();
        Files.createDirectories(folder);
        Path temporary = Files.createTempFile(folder, ".results", ".tmp");
        try {
            Files.writeString(temporary, json + "\n", StandardCharsets.UTF_8);
            Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /** The console table: one row per task with tests passed and points. */
    public static String table(List<TestOutcome> outcomes) {
        Map<Integer, double[]> byTask = new TreeMap<>();
        Map<Integer, String> titles = new TreeMap<>();
        for (TestOutcome t : outcomes) {
            double[] row = byTask.computeIfAbsent(t.task(), k -> new double[4]);
            row[0] += t.passed() ? 1 : 0;
            row[1] += 1;
            row[2] += t.passed() ? t.points() : 0;
            row[3] += t.points();
            titles.put(t.task(), t.taskTitle());
        }
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "%-24s %12s %14s%n", "task", "tests passed", "points"));
        double[] total = new double[4];
        for (Map.Entry<Integer, double[]> e : byTask.entrySet()) {
            double[] r = e.getValue();
            s.append(String.format(Locale.ROOT, "%-24s %5d / %-4d %6s / %-6s%n", "Task " + e.getKey() + " (" + titles.get(e.getKey()) + ")",
                    (int) r[0], (int) r[1], number(r[2]), number(r[3])));
            for (int k = 0; k < 4; k++) {
                total[k] += r[k];
            }
        }
        s.append(String.format(Locale.ROOT, "%-24s %5d / %-4d %6s / %-6s%n", "total", (int) total[0], (int) total[1],
                number(total[2]), number(total[3])));
        return s.toString();
    }

    private static String number(double x) {
        return x == Math.rint(x) ? String.valueOf((long) x) : String.format(Locale.ROOT, "%.1f", x);
    }

    private static String simpleName(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }
}
