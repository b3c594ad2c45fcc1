package ray.accuracy;

import java.util.ArrayList;
import java.util.List;

/** The samples sweep of one pattern ("grid" or "jittered"): its runs by samples per pixel and the power law fitted to their RMSE. */
final class Convergence {
    final String pattern;
    final List<Run> runs;
    /** RMSE ≈ c·N^slope over the runs with a nonzero error; null when fewer than two have one. */
    final PowerLawFit fit;

    private Convergence(String pattern, List<Run> runs, PowerLawFit fit) {
        this.pattern = pattern;
        this.runs = runs;
        this.fit = fit;
    }

    /** The runs of the samples sweep whose label starts with {@code pattern}, or null when there are none. */
    static Convergence of(SceneStudy study, String pattern) {
        List<Run> runs = new ArrayList<>();
        for (Run run : study.runs("samples")) {
            if (run.setting.label.startsWith(pattern + " ")) {
                runs.add(run);
            }
        }
        if (runs.isEmpty()) {
            return null;
        }
        List<Run> positive = new ArrayList<>();
        runs.forEach(r -> {
            if (r.error.rmse > 0) {
                positive.add(r);
            }
        });
        PowerLawFit fit = null;
        if (positive.size() >= 2) {
            double[] x = new double[positive.size()];
            double[] y = new double[positive.size()];
            for (int k = 0; k < x.length; k++) {
                x[k] = positive.get(k).setting.samples;
                y[k] = positive.get(k).error.rmse;
            }
            fit = PowerLawFit.of(x, y);
        }
        return new Convergence(pattern, runs, fit);
    }
}
