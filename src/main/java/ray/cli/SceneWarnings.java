package ray.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;

/**
 * How every command that loads a scene shows its warnings ({@link Scene#warnings()}): each line
 * once, on stderr, as the loader wrote it ({@code FILE:LINE:COL: warning: what}). A warning changes
 * neither the exit status nor the output.
 */
public final class SceneWarnings {
    private SceneWarnings() {
    }

    /** Loads {@code file} as {@link SceneLoader#load(Path, SceneOptions)} does and prints its warnings on {@code err}. */
    public static Scene load(Path file, SceneOptions options, PrintWriter err) {
        Scene scene = SceneLoader.load(file, options);
        print(scene.warnings(), err);
        return scene;
    }

    /** Prints each warning on a line of {@code err}, and flushes it so that it comes before what follows. */
    public static void print(List<String> warnings, PrintWriter err) {
        for (String warning : warnings) {
            err.println(warning);
        }
        err.flush();
    }
}
