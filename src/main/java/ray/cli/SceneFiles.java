package ray.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/** Expands the command line's scene arguments: a file stands for itself, a folder for every *.xml under it. */
final class SceneFiles {
    private SceneFiles() {
    }

    /** The scene files in argument order, each folder's files sorted by path. Missing paths are kept to be reported. */
    static List<Path> expand(List<Path> arguments) {
        List<Path> scenes = new ArrayList<>();
        for (Path argument : arguments) {
            if (Files.isDirectory(argument)) {
                try (Stream<Path> walk = Files.walk(argument)) {
                    scenes.addAll(walk.filter(p -> p.toString().endsWith(".xml") && Files.isRegularFile(p))
                            .sorted().collect(Collectors.toList()));
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            } else {
                scenes.add(argument);
            }
        }
        return scenes;
    }

    /** The scene's name: its file name without ".xml". */
    static String nameOf(Path scene) {
        String fileName = scene.getFileName().toString();
        return fileName.endsWith(".xml") ? fileName.substring(0, fileName.length() - 4) : fileName;
    }
}
