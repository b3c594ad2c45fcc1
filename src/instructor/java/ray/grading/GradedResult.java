package ray.grading;

import com.google.gson.Gson;
import com.google.gson.JsonParseException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * What the class-wide reports need from one results.json: the total score, each task's regular
 * points (tests tagged "taskN" and not "bonus"), the bonus points, which tests passed, and how long
 * the grading took.
 *
 * @param taskPoints regular points earned, by task number
 * @param passed     each test's name → whether it passed
 * @param seconds    the grading's time, as results.json's {@code execution_time} says (0 when it says none)
 */
public record GradedResult(double score, double maxScore, Map<Integer, Double> taskPoints, double bonus,
                           Map<String, Boolean> passed, double seconds) {
    /** No result at all (a missing or unreadable results.json): 0 points, no tests. */
    public static final GradedResult NONE = new GradedResult(0, 0, Map.of(), 0, Map.of());

    /** A result without a grading time. */
    public GradedResult(double score, double maxScore, Map<Integer, Double> taskPoints, double bonus, Map<String, Boolean> passed) {
        this(score, maxScore, taskPoints, bonus, passed, 0);
    }

    public static GradedResult read(Path resultsJson) {
        try {
            return parse(Files.readString(resultsJson, StandardCharsets.UTF_8));
        } catch (IOException | JsonParseException | ClassCastException e) {
            return NONE;
        }
    }

    @SuppressWarnings("unchecked")
    public static GradedResult parse(String json) {
        Map<String, Object> results = new Gson().fromJson(json, Map.class);
        if (results == null) {
            return NONE;
        }
        Map<Integer, Double> taskPoints = new TreeMap<>();
        Map<String, Boolean> passed = new LinkedHashMap<>();
        double bonus = 0;
        for (Map<String, Object> test : (List<Map<String, Object>>) results.getOrDefault("tests", List.of())) {
            double score = number(test.get("score"));
            List<String> tags = (List<String>) test.getOrDefault("tags", List.of());
            passed.put(String.valueOf(test.get("name")), "passed".equals(test.get("status")));
            if (tags.contains("bonus")) {
                bonus += score;
                continue;
            }
            for (String tag : tags) {
                if (tag.matches("task\\d+")) {
                    taskPoints.merge(Integer.parseInt(tag.substring(4)), score, Double::sum);
                }
            }
        }
        return new GradedResult(number(results.get("score")), GradescopeResults.maxScore(results), taskPoints, bonus, passed,
                number(results.get("execution_time")));
    }

    private static double number(Object o) {
        return o instanceof Number n ? n.doubleValue() : 0;
    }
}
