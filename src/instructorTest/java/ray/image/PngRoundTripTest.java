package ray.image;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.math.Vec3;

/** PngWriter → PngReader keeps every pixel's exact bytes, with the image's top row (j = height − 1) first. */
public class PngRoundTripTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /** The linear value that tone-maps (exposure 1) to exactly byte k: (k/255)^2.2. */
    private static double linear(int k) {
        return Math.pow(k / 255.0, 2.2);
    }

    /** Distinct bytes for every pixel (i, j) and channel c of a 2×3 image. */
    private static int byteOf(int i, int j, int c) {
        return 10 + 40 * j + 15 * i + 5 * c;
    }

    private static int[] rgb(BufferedImage picture, int x, int y) {
        int p = picture.getRGB(x, y);
        return new int[] {(p >> 16) & 0xff, (p >> 8) & 0xff, p & 0xff};
    }

    @Test
    public void twoByThreeImageRoundTripsWithTheTopRowFirst() throws Exception {
        Image image = new Image(2, 3);
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 2; i++) {
                image.set(i, j, new Vec3(linear(byteOf(i, j, 0)), linear(byteOf(i, j, 1)), linear(byteOf(i, j, 2))));
            }
        }
        Path file = folder.getRoot().toPath().resolve("small.png");
        PngWriter.write(image, 1, file);

        BufferedImage picture = PngReader.read(file);
        assertEquals(2, picture.getWidth());
        assertEquals(3, picture.getHeight());
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 2; i++) {
                int row = 2 - j;
                int[] expected = {byteOf(i, j, 0), byteOf(i, j, 1), byteOf(i, j, 2)};
                assertArrayEquals("pixel (" + i + ", " + j + ") is PNG row " + row, expected, rgb(picture, i, row));
            }
        }
        // Spelled out: the PNG's top-left pixel is (0, 2), its bottom-left is (0, 0).
        assertArrayEquals(new int[] {90, 95, 100}, rgb(picture, 0, 0));
        assertArrayEquals(new int[] {10, 15, 20}, rgb(picture, 0, 2));
    }

    @Test
    public void exposureAndClampingApplyInTheFile() throws Exception {
        Image image = new Image(3, 1);
        image.set(0, 0, new Vec3(0.25, 0.5, 3));      // × 2: 0.5 → 186, 1 → 255, 6 → 255
        image.set(1, 0, new Vec3(-1, Double.NaN, 0)); // all black
        image.set(2, 0, new Vec3(0.125, 0.0625, 1));  // × 2: 0.25 → 136, 0.125 → 99, 2 → 255
        Path file = folder.getRoot().toPath().resolve("exposed.png");
        PngWriter.write(image, 2, file);
        BufferedImage picture = PngReader.read(file);
        assertArrayEquals(new int[] {186, 255, 255}, rgb(picture, 0, 0));
        assertArrayEquals(new int[] {0, 0, 0}, rgb(picture, 1, 0));
        // 255·0.125^(1/2.2) = 255·0.38877 = 99.14 → 99
        assertArrayEquals(new int[] {136, 99, 255}, rgb(picture, 2, 0));
    }

    @Test(expected = java.io.IOException.class)
    public void readingSomethingThatIsNotAnImageFails() throws Exception {
        Path file = folder.newFile("not.png").toPath();
        java.nio.file.Files.writeString(file, "hello");
        PngReader.read(file);
    }
}
