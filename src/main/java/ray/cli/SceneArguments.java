package ray.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Parameters;
import ray.scene.SceneFiles;

/**
 * The scene arguments of the commands that take many scenes ({@code render}, {@code accuracy}),
 * mixed into each: a file stands for itself, a folder for every *.xml under it.
 */
final class SceneArguments {
    @Parameters(arity = "1..*", paramLabel = "SCENE.xml|DIR", description = "Scene files or folders of them.")
    List<Path> arguments;

    /**
     * The scene files in argument order, each folder's files sorted by path (missing paths are kept,
     * to be reported by whoever reads them); null, after an error line on {@code err}, when there are none.
     */
    List<Path> files(PrintWriter err) {
        List<Path> scenes = new ArrayList<>();
        for (Path argument : arguments) {
            if (Files.isDirectory(argument)) {
                scenes.addAll(SceneFiles.under(argument));
            } else {
                scenes.add(argument);
            }
        }
        if (scenes.isEmpty()) {
            err.println("error: no scene files (*.xml) found in " + arguments);
            return null;
        }
        return scenes;
    }
}
