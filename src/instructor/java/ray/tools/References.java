package ray.tools;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.cli.RenderCommand;
import ray.cli.SceneWarnings;
import ray.image.PngWriter;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneException;
import ray.scene.SceneFiles;
import ray.scene.SceneOptions;
import ray.shading.Course;
import ray.shading.MicrofacetFactor;

/**
 * Renders the reference images: every scene under scenes/ (recursively, except scenes/reference
 * itself) at its full size with the solution code, into {@code scenes/reference/<scene>.png}.
 * The graded render tests compare students' renders with these by {@link ray.image.ImageDiff}.
 *
 * <p>Also writes the folder's README.md and the marker file {@link RenderCommand#REFERENCE_MARKER}
 * (so {@code ray1 render} refuses to write there), and deletes PNGs of scenes that no longer exist.
 *
 * <p>Run by {@code gradle references}; usage {@code References [SCENES-FOLDER [COURSE]]} (default scenes,
 * by the assignment's course; {@code References scenes-2019 2019} renders the 2019 scenes by 2019's conventions).
 */
public final class References {
    static final String README = readme("scenes", "gradle references", "");

    /** The reference folder's README for the scenes under {@code folder}, rendered by {@code command}. */
    static String readme(String folder, String command, String conventions) {
        return "# Reference renders\n"
                + "\n"
                + "These images are made by `" + command + "` (`ray.tools.References`), which renders every\n"
                + "scene under `" + folder + "/` at full size with the instructor's solution" + conventions + ". Do not edit them by hand:\n"
                + "change a scene, then run `" + command + "` again and look at the images before committing.\n"
                + "\n"
                + "The render tests (`src/test/java/ray/endtoend`) compare your renders with these images;\n"
                + "`docs/grading.md` explains how, and `ray1 diff` compares two images yourself.\n"
                + "`ray1 render` refuses to write into this folder (it holds the marker file `"
                + RenderCommand.REFERENCE_MARKER + "`).\n";
    }

    private References() {
    }

    public static void main(String[] args) throws IOException {
        Path scenes = Path.of(args.length > 0 ? args[0] : "scenes");
        Course course = args.length > 1 ? Course.of(args[1]) : null;
        System.exit(run(scenes, SceneOptions.orAssignment(course, null)));
    }

    /** Renders every scene under {@code scenes} into scenes/reference; returns the exit status. */
    static int run(Path scenes) throws IOException {
        return run(scenes, SceneOptions.ofAssignment());
    }

    /** Renders every scene under {@code scenes}, loaded as {@code options} say, into its reference folder. */
    static int run(Path scenes, SceneOptions options) throws IOException {
        Path reference = scenes.resolve("reference");
        Map<String, Path> byName = new TreeMap<>();
        int failures = 0;
        for (Path file : SceneFiles.under(scenes, reference)) {
            Path previous = byName.putIfAbsent(SceneFiles.nameOf(file), file);
            if (previous != null) {
                System.err.println("error: " + file + " and " + previous + " would both render to "
                        + reference.resolve(SceneFiles.nameOf(file) + ".png") + "; rename one");
                failures++;
            }
        }
        if (failures > 0) {
            return 1;
        }
        Files.createDirectories(reference);
        Files.writeString(reference.resolve(RenderCommand.REFERENCE_MARKER),
                "Reference renders, made by gradle references. ray1 render does not write into this folder.\n",
                StandardCharsets.UTF_8);
        Files.writeString(reference.resolve("README.md"), options.course == Course.Y2017 ? README
                : readme(scenes.toString().replace('\\', '/'), "gradle references" + options.course.year,
                        ", by the course's " + options.course.year + " conventions (`ray1 render --course " + options.course.year + "`)"),
                StandardCharsets.UTF_8);
        // Each scene's warnings go to stderr, as ray1 render prints them.
        PrintWriter warnings = new PrintWriter(System.err);
        for (Map.Entry<String, Path> entry : byName.entrySet()) {
            try {
                Scene scene = SceneWarnings.load(entry.getValue(), options, warnings);
                RenderResult result = new Renderer(scene, 0, 0).render();
                Path png = reference.resolve(entry.getKey() + ".png");
                PngWriter.write(result.image, scene.getExposure(), png);
                System.out.printf("%-24s %4dx%-4d %6.2f s  %s%n", entry.getKey(), scene.getWidth(), scene.getHeight(),
                        result.seconds, png);
                if (scene.hasMicrofacetShader()) {
                    // Each microfacet factor alone, for the render tests' report of a microfacet scene that differs.
                    for (MicrofacetFactor factor : MicrofacetFactor.values()) {
                        Scene alone = scene.reload(o -> o.withMicrofacetFactor(factor));
                        Path view = MicrofacetFactor.referenceView(reference, entry.getKey(), factor);
                        Files.createDirectories(view.getParent());
                        PngWriter.write(new Renderer(alone, 0, 0).render().image, alone.getExposure(), view);
                        System.out.printf("%-24s %s%n", "", view);
                    }
                }
            } catch (SceneException e) {
                System.err.println("error: " + e.getMessage());
                failures++;
            }
        }
        // A reference whose scene is gone would otherwise linger and confuse whoever reads the folder.
        try (Stream<Path> pngs = Files.list(reference)) {
            for (Path png : pngs.filter(p -> p.toString().endsWith(".png")).collect(Collectors.toList())) {
                String name = png.getFileName().toString();
                if (!byName.containsKey(name.substring(0, name.length() - ".png".length()))) {
                    Files.delete(png);
                    System.out.println("deleted " + png + " (no such scene)");
                }
            }
        }
        if (failures > 0) {
            System.err.println(failures + " scenes failed");
        }
        return failures == 0 ? 0 : 1;
    }
}
