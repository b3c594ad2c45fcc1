package ray.grading;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * index.html, the class at a glance without a server or a script: the histogram of scores, every
 * test's pass rate with the most failed first (what to explain again in class), and a link to each
 * submission's results.json with the seconds its grading took.
 */
public final class ClassReport {
    private static final int BINS = 10;

    private ClassReport() {
    }

    public static String html(Map<ClassSubmission, GradedResult> graded) {
        StringBuilder h = new StringBuilder("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                + "<title>ray1 grades</title>\n<style>body{font-family:sans-serif;margin:2em}"
                + "table{border-collapse:collapse}td,th{padding:2px 8px;text-align:left}"
                + ".bar{display:inline-block;height:1em;background:#4a7ebb}.fail{background:#c0504d}</style></head><body>\n");
        h.append("<h1>ray1 grades: ").append(graded.size()).append(graded.size() == 1 ? " submission" : " submissions").append("</h1>\n");
        histogram(graded, h);
        passRates(graded, h);
        submissions(graded, h);
        return h.append("</body></html>\n").toString();
    }

    /** Scores in ten bins of the maximum (the top bin also takes scores above it, with bonus points). */
    private static void histogram(Map<ClassSubmission, GradedResult> graded, StringBuilder h) {
        double max = graded.values().stream().mapToDouble(GradedResult::maxScore).max().orElse(0);
        int[] count = new int[BINS];
        for (GradedResult r : graded.values()) {
            int bin = max <= 0 ? 0 : (int) Math.floor(r.score() / max * BINS);
            count[Math.max(0, Math.min(BINS - 1, bin))]++;
        }
        int most = Math.max(1, java.util.Arrays.stream(count).max().orElse(1));
        h.append("<h2 id=\"histogram\">Score histogram</h2>\n<table>\n<tr><th>score</th><th>submissions</th><th></th></tr>\n");
        for (int b = 0; b < BINS; b++) {
            String range = Gradebook.number(max * b / BINS) + (b == BINS - 1 ? " and up" : " to " + Gradebook.number(max * (b + 1) / BINS));
            h.append("<tr><td>").append(range).append("</td><td>").append(count[b]).append("</td><td>")
                    .append(bar(count[b] * 300 / most, "")).append("</td></tr>\n");
        }
        h.append("</table>\n");
    }

    /** Each test's share of submissions that passed it, least passed first (ties by name). */
    private static void passRates(Map<ClassSubmission, GradedResult> graded, StringBuilder h) {
        Map<String, int[]> byTest = new TreeMap<>(); // passed, graded
        for (GradedResult r : graded.values()) {
            r.passed().forEach((test, passed) -> {
                int[] n = byTest.computeIfAbsent(test, k -> new int[2]);
                n[0] += passed ? 1 : 0;
                n[1]++;
            });
        }
        List<Map.Entry<String, int[]>> rows = new ArrayList<>(byTest.entrySet());
        rows.sort(Comparator.comparingDouble((Map.Entry<String, int[]> e) -> (double) e.getValue()[0] / e.getValue()[1]));
        h.append("<h2 id=\"pass-rates\">Pass rate per test, least passed first</h2>\n<table>\n"
                + "<tr><th>test</th><th>passed</th><th>rate</th><th></th></tr>\n");
        for (Map.Entry<String, int[]> e : rows) {
            int[] n = e.getValue();
            double rate = (double) n[0] / n[1];
            h.append("<tr><td>").append(escape(e.getKey())).append("</td><td>").append(n[0]).append(" / ").append(n[1])
                    .append("</td><td>").append(String.format(Locale.ROOT, "%.0f%%", 100 * rate)).append("</td><td>")
                    .append(bar((int) Math.round(200 * rate), "")).append(bar((int) Math.round(200 * (1 - rate)), " fail"))
                    .append("</td></tr>\n");
        }
        h.append("</table>\n");
    }

    /** Each submission's link, students, score and grading time (results.json's execution_time, blank when it has none). */
    private static void submissions(Map<ClassSubmission, GradedResult> graded, StringBuilder h) {
        h.append("<h2 id=\"submissions\">Submissions</h2>\n<table>\n"
                + "<tr><th>submission</th><th>students</th><th>score</th><th>grading seconds</th></tr>\n");
        graded.forEach((s, r) -> h.append("<tr><td><a href=\"").append(escape(link(s.id()))).append("\">").append(escape(s.id()))
                .append("</a></td><td>").append(escape(s.names())).append("</td><td>").append(Gradebook.number(r.score()))
                .append(" / ").append(Gradebook.number(r.maxScore())).append("</td><td class=\"seconds\">")
                .append(r.seconds() > 0 ? String.format(Locale.ROOT, "%.1f", r.seconds()) : "").append("</td></tr>\n"));
        h.append("</table>\n");
    }

    private static String bar(int width, String kind) {
        return width <= 0 ? "" : "<span class=\"bar" + kind + "\" style=\"width:" + width + "px\"></span>";
    }

    /** The relative link to id/results.json, every byte of the id but letters, digits and "-._~" percent-encoded. */
    static String link(String id) {
        StringBuilder encoded = new StringBuilder();
        for (byte b : id.getBytes(StandardCharsets.UTF_8)) {
            char c = (char) (b & 0xff);
            if (c < 128 && (Character.isLetterOrDigit(c) || "-._~".indexOf(c) >= 0)) {
                encoded.append(c);
            } else {
                encoded.append(String.format(Locale.ROOT, "%%%02X", b & 0xff));
            }
        }
        return encoded + "/results.json";
    }

    public static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;").replace("'", "&#39;");
    }
}
