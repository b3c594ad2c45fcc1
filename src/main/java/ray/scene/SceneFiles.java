package ray.scene;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/** Scene files on disk: the *.xml files of a folder tree, and the name a scene goes by. */
public final class SceneFiles {
    private SceneFiles() {
    }

    /** Every *.xml file under {@code folder}, recursively, sorted by path. */
    public static List<Path> under(Path folder) {
        return under(folder, null);
    }

    /** Every *.xml file under {@code folder} except those under {@code except} (null: none), sorted by path. */
    public static List<Path> under(Path folder, Path except) {
        try (Stream<Path> walk = Files.walk(folder)) {
            return walk.filter(p -> p.toString().endsWith(".xml") && Files.isRegularFile(p))
                    .filter(p -> except == null || !p.startsWith(except))
                    .sorted().collect(Collectors.toList());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The scene's name, which its PNG is named after: the file name without ".xml". */
    public static String nameOf(Path scene) {
        String fileName = scene.getFileName().toString();
        return fileName.endsWith(".xml") ? fileName.substring(0, fileName.length() - ".xml".length()) : fileName;
    }
}
