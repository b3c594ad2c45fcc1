package ray.grading;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;

/**
 * gradebook.csv: one row per submission with its id, students' names, emails and student IDs,
 * each task's regular points, the bonus points and the total score (bonus included, as on
 * Gradescope); and lms.csv, for a learning management system's grade import: one row per student
 * with their student ID, name, email and total.
 */
public final class Gradebook {
    private Gradebook() {
    }

    /** What lms.csv's total is: {@code gradeAll --lms-total}. */
    public enum LmsTotal {
        /** Every point earned, bonus included: the gradebook's total, Gradescope's score. */
        score,
        /** The same, but at most the maximum (the regular points), as PrairieLearn counts it. */
        capped,
        /** The regular points only, without the bonus (to enter the bonus in the LMS apart). */
        regular
    }

    public static String csv(Map<ClassSubmission, GradedResult> graded) {
        // Every task any submission was graded on: a submission the grader could not grade has none, and gets 0s.
        TreeSet<Integer> tasks = new TreeSet<>();
        graded.values().forEach(r -> tasks.addAll(r.taskPoints().keySet()));
        List<String> header = new ArrayList<>(List.of("id", "name", "email", "SID"));
        tasks.forEach(t -> header.add("Task " + t));
        header.addAll(List.of("bonus", "total"));
        StringBuilder csv = new StringBuilder(Csv.row(header));
        graded.forEach((s, r) -> {
            List<String> row = new ArrayList<>(List.of(s.id(), s.names(), s.emails(), s.sids()));
            tasks.forEach(t -> row.add(number(r.taskPoints().getOrDefault(t, 0.0))));
            row.add(number(r.bonus()));
            row.add(number(r.score()));
            csv.append(Csv.row(row));
        });
        return csv.toString();
    }

    /**
     * lms.csv: "SID,name,email,total", a row for each student of each submission (a group's
     * students each get the group's total). A submission without students (no entry in Gradescope's
     * submission_metadata.yml) has no one to import it for and is left out; {@link #unnamed} counts them.
     */
    public static String lms(Map<ClassSubmission, GradedResult> graded, LmsTotal total) {
        StringBuilder csv = new StringBuilder(Csv.row(List.of("SID", "name", "email", "total")));
        graded.forEach((s, r) -> {
            for (Submitter student : s.submitters()) {
                csv.append(Csv.row(List.of(student.sid(), student.name(), student.email(), number(total(r, total)))));
            }
        });
        return csv.toString();
    }

    /** The submissions lms.csv leaves out, as no student is named for them. */
    public static long unnamed(Map<ClassSubmission, GradedResult> graded) {
        return graded.keySet().stream().filter(s -> s.submitters().isEmpty()).count();
    }

    static double total(GradedResult r, LmsTotal total) {
        switch (total) {
            case capped:
                return r.maxScore() > 0 ? Math.min(r.score(), r.maxScore()) : r.score();
            case regular:
                return r.taskPoints().values().stream().mapToDouble(Double::doubleValue).sum();
            default:
                return r.score();
        }
    }

    /** Points as people write them: 12, 12.5 (never 12.0 or 12.500000001). */
    public static String number(double x) {
        double rounded = Math.round(x * 1000) / 1000.0;
        return rounded == Math.rint(rounded) ? String.valueOf((long) rounded)
                : String.format(Locale.ROOT, "%.3f", rounded).replaceAll("0+$", "");
    }
}
