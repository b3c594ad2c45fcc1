package ray.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import ray.camera.CameraRayColors;
import ray.image.PngWriter;
import ray.render.RenderResult;
import ray.render.RenderPlan;
import ray.render.Renderer;
import ray.render.SamplePattern;
import ray.render.TaskProbes;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneOptions;

/**
 * {@code ray1 render}: renders scenes to PNG files, per scene a line of figures and a line of its
 * render plan; while any task is still the handout's stub, the run ends with one line that names
 * those tasks and where to start ({@link TaskProbes}).
 */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = {"Renders each scene (a folder means every *.xml in it, recursively) to DIR/<scene-name>.png.",
                "While any task is still the handout's stub, the run ends with a line naming those tasks and where to start."})
public final class RenderCommand extends ManyScenesCommand {
    /**
     * The file that marks a folder of reference renders (scenes/reference, written by the
     * instructor's {@code gradle references}). {@code ray1 render} refuses to write there, so a
     * student's render can never overwrite the images it is graded against.
     */
    public static final String REFERENCE_MARKER = ".references";

    /**
     * The folder inside DIR that {@code --camera-rays} writes its pictures to: they are no renders,
     * so they never replace a scene's render in DIR/&lt;scene&gt;.png (a student checking Task 1 would
     * otherwise lose the images that show the other tasks' work).
     */
    public static final String CAMERA_RAYS_FOLDER = "camera-rays";

    @Option(names = {"-o", "--output"}, paramLabel = "DIR", description = "Output folder (default: ${DEFAULT-VALUE}).")
    Path output = Path.of("out");

    @Option(names = "--samples", paramLabel = "N", description = "Samples per pixel, overriding the scenes' <samples>.")
    Integer samples;

    @Option(names = "--jitter", description = "Place each pixel's samples at random in their grid cells (stratified "
            + "sampling) instead of at the cell centers. The random numbers follow from --seed and the pixel, so the "
            + "image is the same for any thread count.")
    boolean jitter;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1", description = "Seed of --jitter (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--threads", paramLabel = "N", description = "Worker threads (default: one per core).")
    Integer threads;

    @Option(names = "--accel", paramLabel = "bvh|student|none", description = "How boxes, meshes and "
            + "shadow rays are searched: bvh, also spelled framework (the framework's bounding volume hierarchy in each mesh "
            + "and box, boxes around placed groups, shadow rays that stop at the first blocker), student (the same, with "
            + "your BvhTree in each mesh and box) or none (plain linear loops). The image is the same; the time and the "
            + "counts in --stats are not (default: student when your assignment has you write the tree, else bvh).")
    String accel;

    @Option(names = "--camera-rays", description = "Instead of rendering, color each pixel by where its camera ray crosses "
            + "the image plane (Task 1's picture, before any surface works): correct rays shade from black at the lower left "
            + "to red at the lower right, green at the upper left and yellow at the upper right; blue marks rays off their "
            + "camera's rule, magenta rays that cannot see anything (the stubs'). The pictures go to DIR/" + CAMERA_RAYS_FOLDER
            + "/<scene-name>.png, beside the renders, which they never replace.")
    boolean cameraRays;

    @Option(names = "--stats", paramLabel = "FILE.json", description = "Also write the figures as JSON to this file.")
    Path statsFile;

    @Override
    public Integer call() throws IOException {
        OptionChecks.samples(spec.commandLine(), "--samples", samples);
        OptionChecks.atLeastOne(spec.commandLine(), "--threads", threads);
        ray.accel.Acceleration acceleration = accel == null ? ray.accel.Acceleration.ofAssignment()
                : OptionChecks.acceleration(spec.commandLine(), "--accel", accel);
        SceneOptions sceneOptions = courseOptions.sceneOptions(spec.commandLine());
        PrintWriter out = out();
        PrintWriter err = err();
        Path folder = cameraRays ? output.resolve(CAMERA_RAYS_FOLDER) : output;
        // The camera-ray pictures go to a folder of their own, which must be usable too.
        if (!outputUsable(output, "render somewhere else, e.g. -o out")
                || cameraRays && !outputUsable(folder, "render somewhere else, e.g. -o out")) {
            return 1;
        }
        List<Path> files = scenes.files(err);
        if (files == null) {
            return 1;
        }
        List<SceneStats> stats = new ArrayList<>();
        Map<String, Path> written = new HashMap<>();
        int failures = eachScene(files, file -> {
            String name = SceneFiles.nameOf(file);
            Path previous = written.putIfAbsent(name, file);
            if (previous != null) {
                err.println("error: " + file + ": renders to " + folder.resolve(name + ".png") + ", as " + previous + " does; rename one");
                return false;
            }
            Scene scene = SceneWarnings.load(file, sceneOptions, err);
            if (cameraRays) {
                writeCameraRays(scene, folder.resolve(name + ".png"), name, out);
            } else {
                stats.add(render(scene, name, acceleration, out, err));
            }
            return true;
        });
        if (statsFile != null) {
            SceneStats.writeJson(stats, statsFile);
        }
        if (failures > 0) {
            err.println(failures + " of " + files.size() + " scenes failed");
            err.flush();
        }
        // Last, once per run, whatever the scenes: which tasks are still the handout's stubs (the reason
        // a first render shows only the background) and where to start.
        String stubs = TaskProbes.stillStubsLine(TaskProbes.stubs());
        if (stubs != null) {
            out.println(stubs);
            out.flush();
        }
        return failures == 0 ? 0 : 1;
    }

    private SceneStats render(Scene scene, String name, ray.accel.Acceleration acceleration, PrintWriter out, PrintWriter err)
            throws IOException {
        SamplePattern pattern = jitter ? SamplePattern.jittered(seed) : SamplePattern.GRID;
        RenderPlan plan = RenderPlan.of(scene, samples == null ? 0 : samples, pattern).withAcceleration(acceleration);
        Renderer renderer = new Renderer(plan, threads == null ? 0 : threads);
        RenderResult result;
        // On stderr, and only at a terminal: stdout stays one line per scene for scripts.
        try (ProgressBar bar = ProgressBar.show(name, renderer::progress, err, System.console() != null)) {
            result = renderer.render();
        }
        PngWriter.write(result.image, scene.getExposure(), output.resolve(name + ".png"));
        SceneStats s = SceneStats.of(name, scene, result);
        out.println(s.summaryLine());
        out.println(s.planLine());
        return s;
    }

    private static void writeCameraRays(Scene scene, Path target, String name, PrintWriter out) throws IOException {
        PngWriter.write(CameraRayColors.render(scene.getCamera(), scene.getWidth(), scene.getHeight()), 1, target);
        out.println(name + ": camera rays, " + scene.getWidth() + "x" + scene.getHeight() + " -> " + target);
    }
}
