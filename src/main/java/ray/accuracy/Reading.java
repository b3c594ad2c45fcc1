package ray.accuracy;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The written reading of one scene's study: a few sentences, made from its numbers, on how the
 * error falls with samples, which settings are worth their time (the Pareto front) and what each
 * choice sweep changes, so that a reader who skips the tables still gets the point.
 */
public final class Reading {
    /** A share of pixels below this is "practically converged" in the reading. */
    static final double CONVERGED_SHARE = 0.01;

    private Reading() {
    }

    /** The reading as paragraphs of plain text. */
    public static List<String> of(SceneStudy study) {
        List<String> paragraphs = new ArrayList<>();
        Convergence grid = Convergence.of(study, "grid");
        Convergence jittered = Convergence.of(study, "jittered");
        if (grid != null || jittered != null) {
            paragraphs.add(samples(study, grid, jittered));
        }
        paragraphs.add(front(study));
        for (Sweep sweep : study.sweeps) {
            if (sweep.hasBaseline) {
                paragraphs.add(choices(study, sweep));
            }
        }
        if (!study.missing.isEmpty()) {
            paragraphs.add("Not measured in this copy: the " + String.join(" and ", study.missing) + " sweeps (their code is the "
                    + "assignment's answers, so only the instructor's copy has it; docs/accuracy.md shows their results).");
        }
        return paragraphs;
    }

    private static String samples(SceneStudy study, Convergence grid, Convergence jittered) {
        StringBuilder text = new StringBuilder("Samples per pixel: ");
        List<String> fits = new ArrayList<>();
        for (Convergence c : new Convergence[] {grid, jittered}) {
            if (c != null && c.fit != null) {
                fits.add(String.format(Locale.ROOT, "%s RMSE falls as N^%.2f (r² %.2f)", c.pattern, c.fit.slope, c.fit.rSquared));
            }
        }
        text.append(fits.isEmpty() ? "too few nonzero errors to fit a rate" : String.join(", ", fits))
                .append(", against N^−0.5 for independent random samples");
        if (jittered != null && jittered.fit != null) {
            double s = jittered.fit.slope;
            text.append(s < -0.6 ? ": stratifying pays off here, the error falls faster than for random samples"
                    : s > -0.4 ? ": slower than random samples, so the error left is not sampling noise (it is the reference's own, "
                            + "or an edge the samples cannot resolve)" : ": about the rate of random samples, as expected on edges");
        }
        text.append(". ");
        Run first = study.runs("samples").get(0);
        text.append(String.format(Locale.ROOT, "At 1 sample %s of the window's pixels are visibly off", percent(first.error.visibleShare)));
        Run converged = firstBelow(study.runs("samples"), CONVERGED_SHARE);
        if (converged != null) {
            text.append(String.format(Locale.ROOT, "; %s is the cheapest setting with fewer than %s (%s, %.0f× the time of 1 sample)",
                    converged.setting.label, percent(CONVERGED_SHARE), percent(converged.error.visibleShare),
                    converged.seconds() / first.seconds()));
        } else {
            text.append(String.format(Locale.ROOT, "; no setting of the sweep gets below %s", percent(CONVERGED_SHARE)));
        }
        text.append('.');
        return text.toString();
    }

    private static Run firstBelow(List<Run> runs, double share) {
        Run best = null;
        for (Run run : runs) {
            if (run.error.visibleShare < share && (best == null || run.seconds() < best.seconds())) {
                best = run;
            }
        }
        return best;
    }

    /**
     * The front among the samples sweep's settings. The choice sweeps' settings render at the
     * scene's own samples and differ from its baseline by less than the clock's noise in time and,
     * in the window, often not at all in error; their verdict is their defects, in their own paragraph.
     */
    private static String front(SceneStudy study) {
        List<Run> sampled = study.runs("samples");
        List<Run> front = ParetoFront.of(sampled, Run::seconds, r -> r.error.rmse);
        List<String> on = new ArrayList<>();
        front.forEach(r -> on.add(r.setting.label));
        List<String> off = new ArrayList<>();
        for (Run run : sampled) {
            if (!front.contains(run)) {
                off.add(run.setting.label);
            }
        }
        return "Samples worth their time (the Pareto front of RMSE against time: no other setting is both faster and closer): "
                + String.join(", ", on) + ". Not worth it (another is at least as fast and closer): "
                + (off.isEmpty() ? "none" : String.join(", ", off)) + ".";
    }

    private static String choices(SceneStudy study, Sweep sweep) {
        List<Run> runs = study.runs(sweep.name);
        Run baseline = runs.get(0);
        StringBuilder text = new StringBuilder(capitalized(sweep.name)).append(" (against ").append(baseline.setting.label)
                .append("): ");
        List<String> parts = new ArrayList<>();
        for (Run run : runs.subList(1, runs.size())) {
            String cost = String.format(Locale.ROOT, "%.2f× the time", run.seconds() / baseline.seconds());
            String effect = run.defects > 0
                    ? String.format(Locale.ROOT, "changes %s of the image's pixels visibly (%s)", percent(run.defects), defectName(sweep.name))
                    : "changes no pixel visibly";
            parts.add(run.setting.label + " takes " + cost + " and " + effect);
        }
        text.append(String.join("; ", parts)).append('.');
        boolean anyDefect = runs.stream().anyMatch(r -> r.defects > 0);
        if (sweep.name.equals("acceleration")) {
            return text.append(anyDefect ? " The accelerated search must not change the image: this is a bug."
                    : " The same image either way: acceleration is time saved at no cost in accuracy.").toString();
        }
        if (sweep.name.equals("depth")) {
            return text.append(anyDefect ? " Each level of depth adds a ray only where the last one met a mirror, so the cost"
                    + " grows slowly while the visible change shrinks: the depth past which no pixel changes is the one worth paying for."
                    : " No pixel changes: the scene's mirrors do not see each other, so one bounce is enough here.").toString();
        }
        text.append(anyDefect ? " The baseline is worth keeping: the cheaper-looking choices cost image quality here."
                : " Here the choice does not show; the hard-case scenes are where it does.");
        return text.toString();
    }

    /** What visible changes of a choice sweep are, in the numerics issue's words. */
    static String defectName(String sweep) {
        switch (sweep) {
            case "offsets":
                return "shadow acne: rays that hit their own surface";
            case "intersection":
                return "leaks through shared edges, holes and lost silhouettes";
            case "arithmetic":
                return "float's rounding: speckles, acne and lost silhouettes";
            case "acceleration":
                return "a search that differs from the linear loop's";
            case "depth":
                return "reflections cut short: mirrors that show black where a deeper ray would bring back light";
            default:
                return "differences from the baseline";
        }
    }

    static String percent(double share) {
        double p = 100 * share;
        return p == 0 ? "0%" : p < 0.01 ? String.format(Locale.ROOT, "%.1g%%", p) : String.format(Locale.ROOT, "%.2f%%", p);
    }

    private static String capitalized(String s) {
        return Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }
}
