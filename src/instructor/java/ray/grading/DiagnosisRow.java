package ray.grading;

import java.util.List;
import java.util.Set;

/**
 * What the feedback on one {@link DiagnosisCase} named: the mistakes it makes that were named
 * ({@code right}), those it does not make that were named ({@code wrong}), where the names came
 * from (a render match, the unit tests' failures), and whether a failed render was called the
 * reference flipped or mirrored (a measured fact about the picture, not a mistake's name), and how
 * many of the failed render tests with a picture unlike the reference carry a right name or that fact.
 */
record DiagnosisRow(DiagnosisCase of, GradedFeedback feedback, Set<String> right, Set<String> wrong, Set<String> where,
        boolean flippedPicture, int failedRenders, int rendersNamed) {

    int failedTests() {
        return feedback.failed().size();
    }

    /** "12", or "4 (4 bonus)" when some are bonus tests (which correct textbook code may fail). */
    String failedShown() {
        long bonus = feedback.failed().stream().filter(GradedFeedback.Failed::bonus).count();
        return failedTests() + (bonus == 0 ? "" : " (" + bonus + " bonus)");
    }

    /** The verdict: the goal is "named" for every known mistake and never a wrong name. */
    String verdict() {
        if (!wrong.isEmpty()) {
            return "named wrongly";
        }
        switch (of.kind) {
            case WRONG:
                return right.isEmpty() ? (flippedPicture ? "picture named" : "missed") : "named";
            case CORRECT:
                return failedTests() == 0 ? "nothing failed" : "nothing named";
            default:
                return "no wrong name";
        }
    }

    /** Whether this row meets the goal: the known mistake named, and nothing named wrongly. */
    boolean meetsTheGoal() {
        String v = verdict();
        return v.equals("named") || v.equals("picture named") || v.equals("nothing failed") || v.equals("no wrong name");
    }

    String summary() {
        return of.name + ": " + verdict() + (wrong.isEmpty() ? "" : " (" + String.join(", ", wrong) + ")");
    }

    /** The rows as a Markdown table, with a count of each verdict under it. */
    static String table(List<DiagnosisRow> unsorted) {
        // By task, then name; the attempts, graded on every task, last.
        List<DiagnosisRow> rows = new java.util.ArrayList<>(unsorted);
        rows.sort(java.util.Comparator.comparing((DiagnosisRow r) -> r.of.task == null ? Integer.MAX_VALUE : r.of.task)
                .thenComparing(r -> r.of.name));
        StringBuilder md = new StringBuilder("| Task | Submission | Failed tests | Differing renders named | Verdict | Named from | Names given |\n"
                + "|---|---|---|---|---|---|---|\n");
        for (DiagnosisRow r : rows) {
            String names = String.join(", ", r.right) + (r.wrong.isEmpty() ? "" : (r.right.isEmpty() ? "" : "; ") + "wrongly: "
                    + String.join(", ", r.wrong));
            md.append("| ").append(r.of.task == null ? "all" : r.of.task).append(" | ").append(r.of.name)
                    .append(r.of.kind == DiagnosisCase.Kind.CORRECT ? " (correct)" : "").append(" | ").append(r.failedShown())
                    .append(" | ").append(r.failedRenders == 0 ? "–" : r.rendersNamed + " of " + r.failedRenders)
                    .append(" | ").append(r.verdict()).append(" | ").append(String.join(", ", r.where))
                    .append(r.flippedPicture ? (r.where.isEmpty() ? "" : ", ") + "flipped picture" : "").append(" | ")
                    .append(names).append(" |\n");
        }
        java.util.Map<String, Long> counts = new java.util.TreeMap<>();
        rows.forEach(r -> counts.merge(r.verdict(), 1L, Long::sum));
        md.append('\n');
        counts.forEach((verdict, n) -> md.append("- ").append(verdict).append(": ").append(n).append('\n'));
        return md.toString();
    }
}
