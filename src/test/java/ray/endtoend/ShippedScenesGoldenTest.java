package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import ray.image.PngReader;
import ray.image.PngWriter;
import ray.scene.Scene;

/**
 * Renders every shipped scene small and compares it with its golden image in
 * src/test/resources/golden, made by this framework's solution code. Catches any change to a
 * rendering convention, a shader or a student method.
 *
 * <p>Java's floating point is strict, but Math.pow, sin and cos may differ by one ulp between
 * JVMs, which can move a tone-mapped value by one level or flip an edge pixel. So every channel
 * must be within 1 level, except in at most 0.5% of the pixels.
 *
 * <p>After an intended change, rewrite the goldens with {@code gradle test -PupdateGoldens} and
 * look at every one of them before committing.
 */
@RunWith(Parameterized.class)
public class ShippedScenesGoldenTest {
    static final Path GOLDEN = Path.of("src/test/resources/golden");
    static final double MAX_SHARE_OFF_BY_MORE_THAN_ONE = 0.005;

    @Parameters(name = "{0}")
    public static Collection<Object[]> scenes() {
        List<Object[]> list = new ArrayList<>();
        for (Path p : ShippedScenes.all()) {
            list.add(new Object[] {ShippedScenes.nameOf(p), p});
        }
        return list;
    }

    private final String name;
    private final Path file;

    public ShippedScenesGoldenTest(String name, Path file) {
        this.name = name;
        this.file = file;
    }

    @Test(timeout = 60_000)
    public void rendersLikeItsGolden() throws Exception {
        Scene scene = ShippedScenes.loadSmall(file);
        BufferedImage actual = PngWriter.toBufferedImage(ShippedScenes.renderSmall(scene), scene.getExposure());
        Path golden = GOLDEN.resolve(name + ".png");
        if (Boolean.getBoolean("ray1.updateGoldens")) {
            PngWriter.write(actual, golden);
            return;
        }
        if (!Files.exists(golden)) {
            fail("no golden image " + golden + " for scene " + file + "; make it with gradle test -PupdateGoldens");
        }
        BufferedImage expected = PngReader.read(golden);
        assertEquals(name + " width", expected.getWidth(), actual.getWidth());
        assertEquals(name + " height", expected.getHeight(), actual.getHeight());
        int far = 0;
        String firstFar = null;
        for (int y = 0; y < expected.getHeight(); y++) {
            for (int x = 0; x < expected.getWidth(); x++) {
                int e = expected.getRGB(x, y);
                int a = actual.getRGB(x, y);
                int diff = Math.max(Math.abs((e >> 16 & 255) - (a >> 16 & 255)),
                        Math.max(Math.abs((e >> 8 & 255) - (a >> 8 & 255)), Math.abs((e & 255) - (a & 255))));
                if (diff > 1) {
                    far++;
                    if (firstFar == null) {
                        firstFar = String.format("(%d, %d) from the top: expected #%06x, got #%06x", x, y, e & 0xffffff, a & 0xffffff);
                    }
                }
            }
        }
        int allowed = (int) (MAX_SHARE_OFF_BY_MORE_THAN_ONE * expected.getWidth() * expected.getHeight());
        assertTrue(name + ": " + far + " pixels differ by more than one level (allowed " + allowed + "); first at " + firstFar,
                far <= allowed);
    }

    /** A golden must not be trivially passable: it shows more than a few colors. */
    @Test
    public void goldenIsNotAFlatImage() throws Exception {
        Path golden = GOLDEN.resolve(name + ".png");
        if (Boolean.getBoolean("ray1.updateGoldens") || !Files.exists(golden)) {
            return;
        }
        BufferedImage image = PngReader.read(golden);
        java.util.Set<Integer> colors = new java.util.HashSet<>();
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                colors.add(image.getRGB(x, y));
            }
        }
        assertTrue(name + " golden has only " + colors.size() + " colors", colors.size() > 20);
    }
}
