package ray.accuracy;

import java.util.Locale;

/** A scene's runs as a table, in HTML for the report and in Markdown for docs/accuracy.md. */
final class Tables {
    static final String[] HEADER = {"sweep", "setting", "time (ms)", "spread (ms)", "runs", "rays", "RMSE", "max error", "PSNR (dB)",
        "visibly off", "defects"};

    private Tables() {
    }

    /** One row's cells, formatted. */
    static String[] cells(Run run) {
        return new String[] {run.sweep, run.setting.label, milliseconds(run.timing.medianSeconds),
            milliseconds(run.timing.minSeconds) + "–" + milliseconds(run.timing.maxSeconds), Integer.toString(run.timing.runs),
            String.format(Locale.ROOT, "%,d", run.rays), String.format(Locale.ROOT, "%.3g", run.error.rmse),
            String.format(Locale.ROOT, "%.3g", run.error.maxError), String.format(Locale.ROOT, "%.1f", run.error.psnr),
            Reading.percent(run.error.visibleShare), Double.isNaN(run.defects) ? "–" : Reading.percent(run.defects)};
    }

    static String html(SceneStudy study) {
        StringBuilder t = new StringBuilder("<table><tr>");
        for (String h : HEADER) {
            t.append("<th>").append(h).append("</th>");
        }
        t.append("</tr>\n");
        for (Run run : study.runs) {
            t.append("<tr>");
            for (String cell : cells(run)) {
                t.append("<td>").append(ReportWriter.escape(cell)).append("</td>");
            }
            t.append("</tr>\n");
        }
        return t.append("</table>\n").toString();
    }

    static String markdown(SceneStudy study) {
        StringBuilder t = new StringBuilder("### ").append(study.name).append("\n\n");
        t.append(String.format(Locale.ROOT, "Window %s of %d×%d; reference %d jittered spp (%.2f s).%n%n", study.window, study.width,
                study.height, study.referenceSamples, study.referenceSeconds));
        t.append('|').append(String.join("|", HEADER)).append("|\n|");
        for (int k = 0; k < HEADER.length; k++) {
            t.append(k < 2 ? "---|" : "--:|");
        }
        t.append('\n');
        for (Run run : study.runs) {
            t.append('|').append(String.join("|", cells(run))).append("|\n");
        }
        t.append('\n');
        for (String paragraph : Reading.of(study)) {
            t.append(paragraph).append("\n\n");
        }
        return t.toString();
    }

    /** Three significant digits, in milliseconds. */
    static String milliseconds(double seconds) {
        double ms = 1000 * seconds;
        return ms >= 100 ? String.format(Locale.ROOT, "%.0f", ms) : String.format(Locale.ROOT, "%.3g", ms);
    }
}
