package ray.image;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.math.Vec3;

/** How PngWriter treats the file system: it replaces files whole, leaves no temporaries and creates folders. */
public class PngWriterFilesTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private static Image filled(int width, int height, Vec3 color) {
        Image image = new Image(width, height);
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                image.set(i, j, color);
            }
        }
        return image;
    }

    private static List<String> namesIn(Path dir) throws Exception {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().collect(Collectors.toList());
        }
    }

    @Test
    public void writingOverAnExistingFileReplacesItWhole() throws Exception {
        Path dir = folder.getRoot().toPath();
        Path file = dir.resolve("scene.png");
        PngWriter.write(filled(40, 30, new Vec3(1, 0, 0)), 1, file);
        PngWriter.write(filled(3, 2, new Vec3(0, 0.5, 1)), 1, file);

        BufferedImage picture = PngReader.read(file);
        assertEquals("the new size, not the old one", 3, picture.getWidth());
        assertEquals(2, picture.getHeight());
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                assertEquals(0x00baff, picture.getRGB(x, y) & 0xffffff); // (0, 186, 255)
            }
        }
        assertEquals("no temporary files are left beside it", List.of("scene.png"), namesIn(dir));
    }

    @Test
    public void writingOverAnArbitraryFileReplacesIt() throws Exception {
        Path dir = folder.getRoot().toPath();
        Path file = dir.resolve("old.png");
        Files.writeString(file, "not a png, e.g. left by an older tool");
        PngWriter.write(filled(2, 2, Vec3.ONE), 1, file);
        assertEquals(0xffffff, PngReader.read(file).getRGB(1, 1) & 0xffffff);
        assertEquals(List.of("old.png"), namesIn(dir));
    }

    @Test
    public void missingFoldersAreCreated() throws Exception {
        Path file = folder.getRoot().toPath().resolve("a").resolve("b").resolve("c").resolve("deep.png");
        PngWriter.write(filled(1, 1, new Vec3(0.5, 0.5, 0.5)), 1, file);
        assertTrue(Files.isRegularFile(file));
        assertEquals(0xbababa, PngReader.read(file).getRGB(0, 0) & 0xffffff); // 186 = 0xba
        assertEquals(List.of("deep.png"), namesIn(file.getParent()));
    }
}
