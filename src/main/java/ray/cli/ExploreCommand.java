package ray.cli;

import java.io.PrintWriter;
import java.net.BindException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import ray.inspect.Explorer;
import ray.scene.SceneException;

/** {@code ray1 explore}: renders a scene and serves a page where a click on a pixel shows its ray's story. */
@Command(name = "explore", mixinStandardHelpOptions = true,
        description = "Renders the scene and serves a page on http://127.0.0.1:PORT/ that shows the render beside its "
                + "reference and their difference; click a pixel to see its camera ray, every surface it meets, the "
                + "closest hit, the shadow rays and the shading (what ray1 trace prints), drawn from above and the side.")
public final class ExploreCommand implements Callable<Integer> {
    @Option(names = "--port", paramLabel = "N", defaultValue = "8123",
            description = "The port on 127.0.0.1 (default: ${DEFAULT-VALUE}; 0 picks a free one).")
    int port;

    @Option(names = "--reference", paramLabel = "FILE.png", description = "The image to compare with (default: "
            + "reference/<scene-name>.png in the scene's folder or the one above it, e.g. scenes/reference/one-sphere.png).")
    Path reference;

    @Parameters(paramLabel = "SCENE.xml", description = "The scene file.")
    Path sceneFile;

    @CommandLine.Mixin
    Verbosity verbosity;

    @CommandLine.Mixin
    CourseOptions courseOptions;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (port < 0 || port > 65535) {
            throw new CommandLine.ParameterException(spec.commandLine(), "--port must be from 0 to 65535, but was " + port);
        }
        if (reference != null && !Files.isRegularFile(reference)) {
            err.println("error: --reference " + reference + ": no such file; expected a PNG image");
            return 1;
        }
        ray.scene.SceneOptions options = courseOptions.sceneOptions(spec.commandLine());
        Explorer explorer;
        try {
            explorer = Explorer.start(sceneFile, reference, port, options);
        } catch (SceneException e) {
            err.println("error: " + e.getMessage());
            return 1;
        } catch (BindException e) {
            err.println("error: port " + port + " is in use (another ray1 explore?); choose another with --port N, or --port 0"
                    + " for any free one");
            return 1;
        } catch (java.io.IOException | RuntimeException e) {
            verbosity.report(err, sceneFile.toString(), e);
            return 1;
        }
        try (explorer) {
            // Printed once; a re-render from the page shows the scene's warnings there, among its notes.
            SceneWarnings.print(explorer.warnings(), err);
            out.println("ray1 explore: " + sceneFile + " at " + explorer.url() + "  (open it in a browser; Ctrl-C stops)");
            out.flush();
            // Serves until the process is stopped (Ctrl-C): nothing counts this down.
            new CountDownLatch(1).await();
        }
        return 0;
    }
}
