package ray.grading;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;

/**
 * gradebook.csv: one row per submission with its id, students' names and emails, each task's
 * regular points, the bonus points and the total score (bonus included, as on Gradescope).
 */
public final class Gradebook {
    private Gradebook() {
    }

    public static String csv(Map<ClassSubmission, GradedResult> graded) {
        // Every task any submission was graded on: a submission the grader could not grade has none, and gets 0s.
        TreeSet<Integer> tasks = new TreeSet<>();
        graded.values().forEach(r -> tasks.addAll(r.taskPoints().keySet()));
        List<String> header = new ArrayList<>(List.of("id", "name", "email"));
        tasks.forEach(t -> header.add("Task " + t));
        header.addAll(List.of("bonus", "total"));
        StringBuilder csv = new StringBuilder(Csv.row(header));
        graded.forEach((s, r) -> {
            List<String> row = new ArrayList<>(List.of(s.id(), s.names(), s.emails()));
            tasks.forEach(t -> row.add(number(r.taskPoints().getOrDefault(t, 0.0))));
            row.add(number(r.bonus()));
            row.add(number(r.score()));
            csv.append(Csv.row(row));
        });
        return csv.toString();
    }

    /** Points as people write them: 12, 12.5 (never 12.0 or 12.500000001). */
    public static String number(double x) {
        double rounded = Math.round(x * 1000) / 1000.0;
        return rounded == Math.rint(rounded) ? String.valueOf((long) rounded)
                : String.format(Locale.ROOT, "%.3f", rounded).replaceAll("0+$", "");
    }
}
