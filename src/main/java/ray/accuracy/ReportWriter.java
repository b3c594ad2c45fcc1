package ray.accuracy;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Locale;
import ray.image.ImageDiff;
import ray.image.PngWriter;

/**
 * Writes the studies as a report in a folder: {@code index.html} (tables, plots, image strips and
 * readings; no scripts or links outside the folder, so it opens offline), per scene its two plots
 * as SVG and its window images as PNG, and {@code results.md}, the same tables as Markdown for
 * docs/accuracy.md. Every file is written to a temporary name and then moved into place.
 */
public final class ReportWriter {
    /** Windows are shown this many times their size, pixels kept square. */
    static final int ZOOM = 3;

    private ReportWriter() {
    }

    public static void write(List<SceneStudy> studies, Path folder, String command) throws IOException {
        Files.createDirectories(folder);
        StringBuilder html = new StringBuilder();
        html.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>ray1 accuracy report</title>\n<style>\n")
                .append("body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}\n")
                .append("table{border-collapse:collapse;margin:1em 0;font-size:0.9em}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}\n")
                .append("td:first-child,td:nth-child(2),th{text-align:left}img.px{image-rendering:pixelated}\n")
                .append("figure{display:inline-block;margin:4px;text-align:center;font-size:0.8em}figure img{display:block}\n")
                .append(".strip{overflow-x:auto;white-space:nowrap}\n</style></head><body>\n")
                .append("<h1>Accuracy against time</h1>\n<p>Made by <code>").append(escape(command)).append("</code>. ")
                .append("Each scene is rendered with every setting of every sweep. Time and error are measured on a window of the ")
                .append("image (shown below each scene): the wall time is the median of repeated renders of the window (at least ")
                .append(AccuracyStudy.RUNS).append(") with the fastest and slowest run; the error is against a converged jittered ")
                .append("render of the window, in linear radiance (RMSE, largest error, PSNR with the exposure's white as peak) ")
                .append("and as the share of pixels whose displayed value is off by more than 1/255. Defects are counted on the ")
                .append("whole image: the share of pixels that differ visibly from the sweep's baseline (the framework's own choice), ")
                .append("rendered at the scene's samples per pixel.</p>\n");
        html.append(summaryTable(studies));
        StringBuilder markdown = new StringBuilder();
        for (SceneStudy study : studies) {
            Path dir = folder.resolve(study.name);
            Files.createDirectories(dir);
            writeText(dir.resolve("error-time.svg"), Plots.errorAgainstTime(study));
            writeText(dir.resolve("convergence.svg"), Plots.convergence(study));
            writeImages(study, dir);
            html.append(section(study));
            markdown.append(Tables.markdown(study)).append('\n');
        }
        html.append("</body></html>\n");
        writeText(folder.resolve("results.md"), markdown.toString());
        writeText(folder.resolve("index.html"), html.toString());
    }

    private static String summaryTable(List<SceneStudy> studies) {
        StringBuilder t = new StringBuilder("<h2>Summary</h2>\n<table><tr><th>scene</th><th>window</th>"
                + "<th>grid slope</th><th>jittered slope</th><th>visibly off at 1 spp</th><th>largest defect share</th></tr>\n");
        for (SceneStudy s : studies) {
            Convergence grid = Convergence.of(s, "grid");
            Convergence jittered = Convergence.of(s, "jittered");
            Run first = s.runs("samples").get(0);
            Run worst = null;
            for (Run run : s.runs) {
                if (run.defects > 0 && (worst == null || run.defects > worst.defects)) {
                    worst = run;
                }
            }
            t.append("<tr><td><a href=\"#").append(escape(s.name)).append("\">").append(escape(s.name)).append("</a></td><td>")
                    .append(s.window).append("</td><td>").append(slope(grid)).append("</td><td>").append(slope(jittered))
                    .append("</td><td>").append(Reading.percent(first.error.visibleShare)).append("</td><td>")
                    .append(worst == null ? "none" : escape(worst.setting.label) + ": " + Reading.percent(worst.defects))
                    .append("</td></tr>\n");
        }
        return t.append("</table>\n").toString();
    }

    static String slope(Convergence c) {
        return c == null || c.fit == null ? "–" : String.format(Locale.ROOT, "%.2f", c.fit.slope);
    }

    private static String section(SceneStudy s) {
        StringBuilder h = new StringBuilder();
        h.append("<h2 id=\"").append(escape(s.name)).append("\">").append(escape(s.name)).append("</h2>\n<p>")
                .append(s.width).append('×').append(s.height).append(" pixels, ").append(s.sceneSamples)
                .append(" sample(s) per pixel in the scene. Window x,y,w,h = ").append(s.window).append(" (y from the top); reference: ")
                .append(s.referenceSamples).append(" jittered samples per pixel, ")
                .append(String.format(Locale.ROOT, "%.2f s", s.referenceSeconds)).append(".</p>\n");
        for (String paragraph : Reading.of(s)) {
            h.append("<p>").append(escape(paragraph)).append("</p>\n");
        }
        h.append("<p><img src=\"").append(escape(s.name)).append("/error-time.svg\" alt=\"error against time\"> <img src=\"")
                .append(escape(s.name)).append("/convergence.svg\" alt=\"convergence\"></p>\n");
        h.append(Tables.html(s));
        h.append("<h3>Window at each setting, and its difference from the reference</h3>\n");
        h.append(figure(s.name + "/reference.png", "reference", s.window.width, s.window.height));
        for (Sweep sweep : s.sweeps) {
            h.append("<div class=\"strip\">");
            for (Run run : s.runs(sweep.name)) {
                String slug = slug(run.setting.label);
                h.append("<figure><img class=\"px\" src=\"").append(escape(s.name + "/" + slug + ".png")).append("\" width=\"")
                        .append(ZOOM * s.window.width).append("\" alt=\"\"><img class=\"px\" src=\"")
                        .append(escape(s.name + "/" + slug + "-diff.png")).append("\" width=\"").append(ZOOM * s.window.width)
                        .append("\" alt=\"\">").append(escape(run.setting.label)).append("</figure>");
            }
            h.append("</div>\n");
        }
        boolean anyDefects = s.runs.stream().anyMatch(r -> r.defectMap != null);
        if (anyDefects) {
            h.append("<h3>Where the defects are (whole image against the sweep's baseline)</h3>\n<div class=\"strip\">");
            for (Run run : s.runs) {
                if (run.defectMap != null) {
                    h.append("<figure><img src=\"").append(escape(s.name + "/" + slug(run.setting.label) + "-defects.png"))
                            .append("\" alt=\"\">").append(escape(run.setting.label)).append(": ")
                            .append(Reading.percent(run.defects)).append("</figure>");
                }
            }
            h.append("</div>\n");
        }
        return h.toString();
    }

    private static String figure(String src, String caption, int width, int height) {
        return "<figure><img class=\"px\" src=\"" + escape(src) + "\" width=\"" + ZOOM * width + "\" height=\"" + ZOOM * height
                + "\" alt=\"\">" + escape(caption) + "</figure>\n";
    }

    private static void writeImages(SceneStudy s, Path dir) throws IOException {
        BufferedImage reference = PngWriter.toBufferedImage(s.reference, s.exposure);
        writePng(reference, dir.resolve("reference.png"));
        for (Run run : s.runs) {
            String slug = slug(run.setting.label);
            BufferedImage window = PngWriter.toBufferedImage(run.window, s.exposure);
            writePng(window, dir.resolve(slug + ".png"));
            writePng(ImageDiff.compare(reference, window, 0, 0).heatMap(), dir.resolve(slug + "-diff.png"));
            if (run.defectMap != null) {
                writePng(run.defectMap, dir.resolve(slug + "-defects.png"));
            }
        }
    }

    /** A file name for a label: "jittered 16" → "jittered-16", "offset fixed 1e-6" → "offset-fixed-1e-6". */
    static String slug(String label) {
        return label.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9.+-]+", "-").replaceAll("^-|-$", "");
    }

    private static void writePng(BufferedImage picture, Path target) throws IOException {
        PngWriter.write(picture, target);
    }

    private static void writeText(Path target, String text) throws IOException {
        Path temporary = Files.createTempFile(target.toAbsolutePath().getParent(), ".accuracy-", ".tmp");
        try {
            Files.write(temporary, text.getBytes(StandardCharsets.UTF_8));
            Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
