package ray.accuracy;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** The two plots of a scene's study, as SVG documents. */
final class Plots {
    /** One color per sweep, in {@link Sweeps#ALL} order, then gray. */
    private static final Map<String, String> COLORS = new LinkedHashMap<>();

    static {
        COLORS.put("samples", "#1f77b4");
        COLORS.put("arithmetic", "#d62728");
        COLORS.put("intersection", "#9467bd");
        COLORS.put("fresnel", "#e377c2");
        COLORS.put("masking", "#17becf");
        COLORS.put("offsets", "#2ca02c");
        COLORS.put("depth", "#8c564b");
        COLORS.put("acceleration", "#ff7f0e");
    }

    private Plots() {
    }

    /** RMSE against time, every run a labelled point colored by sweep, with the Pareto front. */
    static String errorAgainstTime(SceneStudy study) {
        LogLogPlot plot = new LogLogPlot(study.name + ": error against time", "time of the window's render (s, median)",
                "RMSE against the reference");
        List<Run> plotted = new ArrayList<>();
        for (Sweep sweep : study.sweeps) {
            List<LogLogPlot.Point> points = new ArrayList<>();
            for (Run run : study.runs(sweep.name)) {
                if (run.error.rmse > 0) {
                    points.add(new LogLogPlot.Point(run.seconds(), run.error.rmse, run.setting.label));
                    plotted.add(run);
                }
            }
            if (!points.isEmpty()) {
                plot.points(sweep.name, COLORS.getOrDefault(sweep.name, "#7f7f7f"), points);
            }
        }
        List<LogLogPlot.Point> front = new ArrayList<>();
        for (Run run : ParetoFront.of(plotted, Run::seconds, r -> r.error.rmse)) {
            front.add(new LogLogPlot.Point(run.seconds(), run.error.rmse, null));
        }
        if (front.size() >= 2) {
            plot.line("Pareto front", "#444444", false, front);
        }
        return plot.toSvg();
    }

    /** RMSE against samples per pixel for grid and jittered, their fitted power laws and the N^−½ rate. */
    static String convergence(SceneStudy study) {
        LogLogPlot plot = new LogLogPlot(study.name + ": convergence", "samples per pixel N", "RMSE against the reference");
        String[][] patterns = {{"grid", "#1f77b4"}, {"jittered", "#ff7f0e"}};
        Convergence anchor = null;
        for (String[] p : patterns) {
            Convergence c = Convergence.of(study, p[0]);
            if (c == null) {
                continue;
            }
            List<LogLogPlot.Point> points = new ArrayList<>();
            for (Run run : c.runs) {
                if (run.error.rmse > 0) {
                    points.add(new LogLogPlot.Point(run.setting.samples, run.error.rmse, null));
                }
            }
            if (points.isEmpty()) {
                continue;
            }
            plot.line(p[0], p[1], false, points).points(null, p[1], points);
            if (c.fit != null) {
                double lo = c.runs.get(0).setting.samples;
                double hi = c.runs.get(c.runs.size() - 1).setting.samples;
                plot.line(String.format(java.util.Locale.ROOT, "%s fit N^%.2f", p[0], c.fit.slope), p[1], true,
                        List.of(new LogLogPlot.Point(lo, c.fit.at(lo), null), new LogLogPlot.Point(hi, c.fit.at(hi), null)));
                anchor = p[0].equals("jittered") || anchor == null ? c : anchor;
            }
        }
        if (anchor != null) {
            // The rate of independent random samples, through the fit's value at the first count.
            double lo = anchor.runs.get(0).setting.samples;
            double hi = anchor.runs.get(anchor.runs.size() - 1).setting.samples;
            double at = anchor.fit.at(lo);
            plot.line("ideal N^-0.5", "#7f7f7f", true,
                    List.of(new LogLogPlot.Point(lo, at, null), new LogLogPlot.Point(hi, at * Math.sqrt(lo / hi), null)));
        }
        return plot.toSvg();
    }
}
