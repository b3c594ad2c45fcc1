package ray.endtoend;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Properties;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.image.ImageDiff;
import ray.image.PngWriter;
import ray.testing.StudentTask;

/**
 * The student's picture of failed render tests: build/reports/render-diff/index.html shows, for
 * every scene that did not match, their render, the reference and the heat map side by side, with
 * the figures. The PNGs are copied beside the page, so it works offline and after the next build.
 *
 * <p>Each test class owns a folder {@code render-diff/<ClassName>/} with one
 * {@code <scene>.properties} and three PNGs per failed scene. A class clears its folder when it
 * starts, and index.html is rebuilt from every folder present after each change, so several test
 * classes contribute to one page and a fixed scene drops out of it on the next run.
 */
final class RenderDiffReport {
    static final Path FOLDER = Path.of("build", "reports", "render-diff");
    static final Path INDEX = FOLDER.resolve("index.html");

    private RenderDiffReport() {
    }

    /** Forgets the entries {@code testClass} made in earlier runs, and rebuilds the page without them. */
    static synchronized void clear(Class<?> testClass) {
        Path folder = FOLDER.resolve(testClass.getSimpleName());
        try {
            if (Files.isDirectory(folder)) {
                try (Stream<Path> walk = Files.walk(folder)) {
                    for (Path p : walk.sorted(Comparator.reverseOrder()).collect(Collectors.toList())) {
                        Files.delete(p);
                    }
                }
            }
            writeIndex();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot clear the render report " + folder, e);
        }
    }

    /** Adds a failed scene to the report and returns the page's location, to name in the failure message. */
    static synchronized String add(Class<?> testClass, String scene, StudentTask task, ImageDiff.Result result,
            BufferedImage yours, BufferedImage reference) {
        Path folder = FOLDER.resolve(testClass.getSimpleName());
        try {
            Files.createDirectories(folder);
            PngWriter.write(yours, folder.resolve(scene + "-yours.png"));
            PngWriter.write(reference, folder.resolve(scene + "-reference.png"));
            if (result.sameSize()) {
                PngWriter.write(result.heatMap(), folder.resolve(scene + "-diff.png"));
            }
            Properties entry = new Properties();
            entry.setProperty("scene", scene);
            entry.setProperty("task", task.label());
            entry.setProperty("files", String.join(" and ", task.files));
            entry.setProperty("testClass", testClass.getName());
            entry.setProperty("summary", result.summary());
            entry.setProperty("heatMap", Boolean.toString(result.sameSize()));
            try (Writer w = Files.newBufferedWriter(folder.resolve(scene + ".properties"), StandardCharsets.UTF_8)) {
                entry.store(w, null);
            }
            writeIndex();
        } catch (IOException e) {
            // The test fails anyway; a report that cannot be written must not hide why.
            return "(the report could not be written: " + e + ")";
        }
        return INDEX.toAbsolutePath().toUri().toString();
    }

    /** Rebuilds index.html from every entry under the report folder, by test class and scene. */
    static void writeIndex() throws IOException {
        List<Path> entries = new ArrayList<>();
        if (Files.isDirectory(FOLDER)) {
            try (Stream<Path> walk = Files.walk(FOLDER, 2)) {
                walk.filter(p -> p.toString().endsWith(".properties")).sorted().forEach(entries::add);
            }
        }
        StringBuilder html = new StringBuilder();
        html.append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n")
                .append("<title>ray1: render differences</title>\n<style>\n")
                .append("body { font-family: sans-serif; margin: 1.5em; background: #f4f4f4; color: #222; }\n")
                .append("section { background: #fff; border: 1px solid #ccc; border-radius: 6px; padding: 0.5em 1em 1em; margin-bottom: 1.5em; }\n")
                .append("h2 { margin: 0.4em 0; } .fail { color: #b00; } code { background: #eee; padding: 0 0.2em; }\n")
                .append(".row { display: flex; gap: 1em; flex-wrap: wrap; } figure { margin: 0; }\n")
                .append("figcaption { font-weight: bold; margin-bottom: 0.3em; }\n")
                .append("img { border: 1px solid #888; image-rendering: pixelated; max-width: 100%; }\n")
                .append(".ramp span { display: inline-block; width: 1.2em; height: 1em; vertical-align: middle; border: 1px solid #888; }\n")
                .append("</style>\n</head>\n<body>\n<h1>Render tests: scenes that do not match their reference</h1>\n");
        if (entries.isEmpty()) {
            html.append("<p>No render test failed in the last run.</p>\n");
        } else {
            html.append("<p>").append(entries.size()).append(entries.size() == 1 ? " scene differs" : " scenes differ")
                    .append(" from the reference images in <code>scenes/reference</code>. A scene passes when at most ")
                    .append(percent(ImageDiff.MAX_SHARE)).append(" of its pixels differ by more than ")
                    .append(ImageDiff.TOLERANCE_LEVELS).append(" levels (of 255) in some channel; docs/grading.md explains why.</p>\n")
                    .append("<p>Each scene is graded under one task, but a render runs every part of your ray tracer, so a ")
                    .append("difference can come from any of them; the unit tests of each task narrow it down.</p>\n")
                    .append("<p class=\"ramp\">Heat map: <span style=\"background:#000\"></span> equal, ")
                    .append("<span style=\"background:#0000a0\"></span> within the tolerance, ")
                    .append("<span style=\"background:#c00000\"></span> <span style=\"background:#ff8000\"></span> ")
                    .append("<span style=\"background:#ffff00\"></span> <span style=\"background:#ffffff\"></span> ")
                    .append("beyond it, brighter for larger differences.</p>\n");
        }
        for (Path file : entries) {
            Properties entry = new Properties();
            try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
                entry.load(r);
            }
            String folder = file.getParent().getFileName().toString();
            String scene = entry.getProperty("scene", "?");
            html.append("<section id=\"").append(escape(folder + "-" + scene)).append("\">\n<h2 class=\"fail\">")
                    .append(escape(scene)).append("</h2>\n<p>").append(escape(entry.getProperty("task", "")))
                    .append(": work in <code>").append(escape(entry.getProperty("files", ""))).append("</code>. Test class <code>")
                    .append(escape(entry.getProperty("testClass", ""))).append("</code>.</p>\n<p>")
                    .append(escape(entry.getProperty("summary", ""))).append("</p>\n<div class=\"row\">\n");
            figure(html, folder + "/" + scene + "-yours.png", "Your render");
            figure(html, folder + "/" + scene + "-reference.png", "Reference");
            if (Boolean.parseBoolean(entry.getProperty("heatMap"))) {
                figure(html, folder + "/" + scene + "-diff.png", "Difference");
            }
            html.append("</div>\n<p>Render it yourself: <code>gradle run --args=\"render -o out scenes/").append(escape(scene))
                    .append(".xml\"</code>, then compare: <code>gradle run --args=\"diff scenes/reference/").append(escape(scene))
                    .append(".png out/").append(escape(scene)).append(".png -o out/").append(escape(scene))
                    .append("-diff.png\"</code></p>\n</section>\n");
        }
        html.append("</body>\n</html>\n");
        Files.createDirectories(FOLDER);
        Path temporary = Files.createTempFile(FOLDER, ".index", ".tmp");
        try {
            Files.writeString(temporary, html, StandardCharsets.UTF_8);
            Files.move(temporary, INDEX, StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    private static void figure(StringBuilder html, String src, String caption) {
        html.append("<figure><figcaption>").append(caption).append("</figcaption><a href=\"").append(escape(src))
                .append("\"><img src=\"").append(escape(src)).append("\" alt=\"").append(caption).append("\"></a></figure>\n");
    }

    private static String percent(double share) {
        return java.math.BigDecimal.valueOf(100 * share).stripTrailingZeros().toPlainString() + "%";
    }

    private static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
