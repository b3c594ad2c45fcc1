package ray.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import ray.scene.SceneFiles;

/** Expands the command line's scene arguments: a file stands for itself, a folder for every *.xml under it. */
final class SceneArguments {
    private SceneArguments() {
    }

    /** The scene files in argument order, each folder's files sorted by path. Missing paths are kept to be reported. */
    static List<Path> expand(List<Path> arguments) {
        List<Path> scenes = new ArrayList<>();
        for (Path argument : arguments) {
            if (Files.isDirectory(argument)) {
                scenes.addAll(SceneFiles.under(argument));
            } else {
                scenes.add(argument);
            }
        }
        return scenes;
    }
}
