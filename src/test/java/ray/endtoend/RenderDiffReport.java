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
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Properties;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.image.ImageDiff;
import ray.image.PngWriter;
import ray.testing.ProjectFolder;
import ray.testing.StudentTask;

/**
 * The student's picture of failed render tests: build/reports/render-diff/index.html shows, for
 * every scene that did not match, their render, the reference and the heat map side by side, with
 * the figures. The PNGs are copied beside the page, so it works offline and after the next build.
 *
 * <p>Each test class owns a folder {@code render-diff/<ClassName>/} with one
 * {@code <scene>.properties} and three PNGs per failed scene, and a {@code run.txt} of every scene
 * it rendered (so the page can say how many matched, or that none ran). A class clears its folder when it
 * starts, and index.html is rebuilt from every folder present after each change, so several test
 * classes contribute to one page and a fixed scene drops out of it on the next run.
 */
final class RenderDiffReport {
    /** The report the render tests write, once made: see {@link #build()}. */
    private static RenderDiffReport build;

    /**
     * The report the render tests write, in the project's build folder wherever the tests run from
     * ({@link ProjectFolder}), so an IDE's run adds to the page Gradle's run writes.
     */
    static synchronized RenderDiffReport build() {
        // One instance, made on first use: its methods synchronize on it, for tests in several threads.
        if (build == null) {
            build = new RenderDiffReport(ProjectFolder.resolve("build", "reports", "render-diff"));
        }
        return build;
    }

    /** Per test class, each scene it rendered in its last run and whether it matched: scene=true|false. */
    private static final String RUN_FILE = "run.txt";

    private final Path folder;

    RenderDiffReport(Path folder) {
        this.folder = folder;
    }

    Path index() {
        return folder.resolve("index.html");
    }

    /** Forgets the entries {@code testClass} made in earlier runs, and rebuilds the page without them. */
    static void clear(Class<?> testClass) {
        build().clearEntries(testClass);
    }

    /** Records that {@code testClass} rendered {@code scene}, matched or not, for the page's count. */
    static void ran(Class<?> testClass, String scene, boolean passed) {
        build().record(testClass, scene, passed);
    }

    /**
     * Adds a failed scene to the report; {@code findings} (which tasks the scene uses, what the
     * differing pixels show) heads its entry, as it heads the failure message.
     */
    static String add(Class<?> testClass, String scene, Path sceneFile, StudentTask task, ImageDiff.Result result,
            BufferedImage yours, BufferedImage reference, String findings, List<MicrofacetFactorViews.View> factors) {
        return build().addEntry(testClass, scene, sceneFile, task, result, yours, reference, findings, factors);
    }

    synchronized void clearEntries(Class<?> testClass) {
        Path classFolder = folder.resolve(testClass.getSimpleName());
        try {
            if (Files.isDirectory(classFolder)) {
                try (Stream<Path> walk = Files.walk(classFolder)) {
                    for (Path p : walk.sorted(Comparator.reverseOrder()).collect(Collectors.toList())) {
                        Files.delete(p);
                    }
                }
            }
            writeIndex();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot clear the render report " + classFolder, e);
        }
    }

    synchronized void record(Class<?> testClass, String scene, boolean passed) {
        Path classFolder = folder.resolve(testClass.getSimpleName());
        try {
            Files.createDirectories(classFolder);
            Files.writeString(classFolder.resolve(RUN_FILE), scene + "=" + passed + "\n", StandardCharsets.UTF_8,
                    StandardOpenOption.CREATE, StandardOpenOption.APPEND);
            writeIndex();
        } catch (IOException e) {
            // The count on the page is a convenience; the test's own result stands without it.
        }
    }

    /** Adds a failed scene to the report and returns the page's location, to name in the failure message. */
    synchronized String addEntry(Class<?> testClass, String scene, Path sceneFile, StudentTask task,
            ImageDiff.Result result, BufferedImage yours, BufferedImage reference, String findings, List<MicrofacetFactorViews.View> factors) {
        Path classFolder = folder.resolve(testClass.getSimpleName());
        try {
            Files.createDirectories(classFolder);
            PngWriter.write(yours, classFolder.resolve(scene + "-yours.png"));
            PngWriter.write(reference, classFolder.resolve(scene + "-reference.png"));
            List<String> factorNames = new ArrayList<>();
            for (MicrofacetFactorViews.View view : factors) {
                String prefix = scene + "-" + view.factor().name();
                PngWriter.write(view.yours(), classFolder.resolve(prefix + "-yours.png"));
                PngWriter.write(view.reference(), classFolder.resolve(prefix + "-reference.png"));
                factorNames.add(view.factor().name() + ":" + view.result().passed());
            }
            if (result.sameSize()) {
                PngWriter.write(result.heatMap(), classFolder.resolve(scene + "-diff.png"));
            }
            Properties entry = new Properties();
            entry.setProperty("scene", scene);
            // The path as the student types it in the project folder (scenes/hard/x.xml, not scenes/x.xml
            // nor the absolute path the test read), with / on every system.
            entry.setProperty("file", RenderScenes.shown(sceneFile).toString().replace('\\', '/'));
            entry.setProperty("task", task.label());
            entry.setProperty("findings", findings);
            entry.setProperty("testClass", testClass.getName());
            entry.setProperty("summary", result.summary());
            entry.setProperty("heatMap", Boolean.toString(result.sameSize()));
            // D:false,F:true,G:true: each microfacet factor's view, and whether it matches its reference.
            entry.setProperty("factors", String.join(",", factorNames));
            try (Writer w = Files.newBufferedWriter(classFolder.resolve(scene + ".properties"), StandardCharsets.UTF_8)) {
                entry.store(w, null);
            }
            writeIndex();
        } catch (IOException e) {
            // The test fails anyway; a report that cannot be written must not hide why.
            return "(the report could not be written: " + e + ")";
        }
        return index().toAbsolutePath().toUri() + "#" + sectionId(testClass.getSimpleName(), scene);
    }

    /** Rebuilds index.html from every entry under the report folder, by test class and scene. */
    void writeIndex() throws IOException {
        List<Path> entries = new ArrayList<>();
        int rendered = 0;
        if (Files.isDirectory(folder)) {
            try (Stream<Path> walk = Files.walk(folder, 2)) {
                for (Path p : walk.sorted().collect(Collectors.toList())) {
                    if (p.toString().endsWith(".properties")) {
                        entries.add(p);
                    } else if (p.getFileName().toString().equals(RUN_FILE)) {
                        rendered += Files.readAllLines(p, StandardCharsets.UTF_8).size();
                    }
                }
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
        if (rendered == 0) {
            html.append("<p>No render test has run yet: <code>gradle test</code> runs them.</p>\n");
        } else if (entries.isEmpty()) {
            html.append("<p>Every scene the last run rendered (").append(rendered)
                    .append(") matches its reference.</p>\n");
        } else {
            html.append("<p>").append(entries.size()).append(" of ").append(rendered)
                    .append(" scenes rendered in the last run differ")
                    .append(" from the reference images in <code>scenes/reference</code>. A scene passes when at most ")
                    .append(percent(ImageDiff.MAX_SHARE)).append(" of its pixels differ by more than ")
                    .append(ImageDiff.TOLERANCE_LEVELS).append(" levels (of 255) in some channel; docs/grading.md explains why.</p>\n")
                    .append("<p>A render runs every task its scene uses, so start with a task whose unit tests fail: the ")
                    .append("test summary lists the scene under it. When all of them pass, the surfaces the differing pixels ")
                    .append("show and <code>ray1 trace</code> on the worst pixel say where your code and the reference part.</p>\n")
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
            String classFolder = file.getParent().getFileName().toString();
            String scene = entry.getProperty("scene", "?");
            html.append("<section id=\"").append(escape(sectionId(classFolder, scene))).append("\">\n<h2 class=\"fail\">")
                    .append(escape(scene)).append("</h2>\n");
            for (String finding : entry.getProperty("findings", "").split("\n")) {
                if (!finding.isBlank()) {
                    html.append("<p>").append(escape(finding.strip())).append("</p>\n");
                }
            }
            html.append("<p>").append(escape(entry.getProperty("summary", ""))).append("</p>\n<p>Graded under ")
                    .append(escape(entry.getProperty("task", ""))).append(" by <code>")
                    .append(escape(entry.getProperty("testClass", ""))).append("</code>.</p>\n<div class=\"row\">\n");
            figure(html, classFolder + "/" + scene + "-yours.png", "Your render");
            figure(html, classFolder + "/" + scene + "-reference.png", "Reference");
            if (Boolean.parseBoolean(entry.getProperty("heatMap"))) {
                figure(html, classFolder + "/" + scene + "-diff.png", "Difference");
            }
            html.append("</div>\n");
            for (String factor : entry.getProperty("factors", "").split(",")) {
                if (factor.isEmpty()) {
                    continue;
                }
                String name = factor.substring(0, factor.indexOf(':'));
                boolean matches = Boolean.parseBoolean(factor.substring(factor.indexOf(':') + 1));
                html.append("<p>").append(escape(name)).append(" alone").append(matches ? " (matches)" : " <span class=\"fail\">(differs)</span>")
                        .append(":</p>\n<div class=\"row\">\n");
                figure(html, classFolder + "/" + scene + "-" + name + "-yours.png", "Yours");
                figure(html, classFolder + "/" + scene + "-" + name + "-reference.png", "Reference");
                html.append("</div>\n");
            }
            String sceneFile = entry.getProperty("file", "scenes/" + scene + ".xml");
            html.append("<p>Render it yourself: <code>gradle run --args=\"render -o out ").append(escape(sceneFile))
                    .append("\"</code>, then compare: <code>gradle run --args=\"diff scenes/reference/").append(escape(scene))
                    .append(".png out/").append(escape(scene)).append(".png -o out/").append(escape(scene))
                    .append("-diff.png\"</code></p>\n</section>\n");
        }
        html.append("</body>\n</html>\n");
        Files.createDirectories(folder);
        Path temporary = Files.createTempFile(folder, ".index", ".tmp");
        try {
            Files.writeString(temporary, html, StandardCharsets.UTF_8);
            Files.move(temporary, index(), StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }

    /** The id of a scene's section on the page, the anchor a failure message links to. */
    private static String sectionId(String testClassName, String scene) {
        return testClassName + "-" + scene;
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
