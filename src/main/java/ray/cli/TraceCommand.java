package ray.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import ray.scene.Scene;
import ray.scene.SceneException;
import ray.inspect.PixelTrace;

/** {@code ray1 trace}: explains how one pixel of a scene gets its color. */
@Command(name = "trace", mixinStandardHelpOptions = true,
        description = {
            "Explains one pixel: the camera ray through its center, every surface tested against it, the closest hit,"
                + " each light's part (shadow ray and blocker, the shading terms) and the pixel's 8-bit value,"
                + " which equals that pixel of the PNG from `ray1 render`.",
            "X counts from the left and Y from the TOP, as an image viewer shows the PNG (the top-left pixel is 0 0).",
            "Surfaces and triangles are numbered from 1, in scene and file order."})
public final class TraceCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "SCENE.xml", description = "The scene file.")
    Path sceneFile;

    @Parameters(index = "1", paramLabel = "X", description = "The pixel's column, from 0 at the left.")
    int x;

    @Parameters(index = "2", paramLabel = "Y", description = "The pixel's row, from 0 at the TOP.")
    int y;

    @Option(names = "--all", description = "List every triangle of meshes and boxes instead of one summary line each.")
    boolean all;

    @Option(names = "--samples", paramLabel = "N", description = "Samples per pixel, as for `ray1 render --samples`.")
    Integer samples;

    @CommandLine.Mixin
    Verbosity verbosity;

    @CommandLine.Mixin
    CourseOptions courseOptions;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() {
        OptionChecks.samples(spec.commandLine(), "--samples", samples);
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        ray.scene.SceneOptions options = courseOptions.sceneOptions(spec.commandLine());
        Scene scene;
        try {
            scene = SceneWarnings.load(sceneFile, options, err);
        } catch (SceneException e) {
            err.println("error: " + e.getMessage());
            return 1;
        } catch (RuntimeException e) {
            verbosity.report(err, sceneFile.toString(), e);
            return 1;
        }
        String problem = PixelTrace.outOfRange(scene, sceneFile.toString(), x, y);
        if (problem != null) {
            err.println("error: " + problem);
            return 1;
        }
        PixelTrace trace = new PixelTrace(scene, sceneFile.toString(), all, samples == null ? 0 : samples);
        int[] rgb = trace.run(x, y, out);
        out.flush();
        return rgb != null ? 0 : 1;
    }
}
