package ray.image;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.util.Random;
import org.junit.Test;

/**
 * {@link ImageDiff} on hand-made images: the per-pixel difference is the largest channel
 * difference, only differences beyond {@link ImageDiff#TOLERANCE_LEVELS} count, the verdict turns
 * exactly at {@link ImageDiff#MAX_SHARE}, different sizes fail without an exception, and the heat
 * map's colors follow the difference.
 */
public class ImageDiffTest {
    /** A seeded random image whose channels stay in 20..235, so ±10 never leaves 0..255. */
    private static BufferedImage randomImage(int width, int height, long seed) {
        Random random = new Random(seed);
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, (20 + random.nextInt(216)) << 16 | (20 + random.nextInt(216)) << 8 | (20 + random.nextInt(216)));
            }
        }
        return image;
    }

    private static BufferedImage copy(BufferedImage image) {
        BufferedImage out = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                out.setRGB(x, y, image.getRGB(x, y));
            }
        }
        return out;
    }

    /** Adds dr, dg, db to the channels of pixel (x, y). */
    private static void shift(BufferedImage image, int x, int y, int dr, int dg, int db) {
        int c = image.getRGB(x, y);
        image.setRGB(x, y, ((c >> 16 & 255) + dr) << 16 | ((c >> 8 & 255) + dg) << 8 | ((c & 255) + db));
    }

    @Test
    public void identicalImagesHaveNoDifferenceAndPass() {
        BufferedImage a = randomImage(20, 10, 1);
        ImageDiff.Result r = ImageDiff.compare(a, copy(a));
        assertTrue(r.sameSize());
        assertEquals(0, r.maxDifference());
        assertEquals(0.0, r.meanDifference(), 0);
        assertEquals(0, r.differingPixels());
        assertEquals(0.0, r.differingShare(), 0);
        assertTrue(r.toString(), r.passed());
        BufferedImage map = r.heatMap();
        for (int y = 0; y < 10; y++) {
            for (int x = 0; x < 20; x++) {
                assertEquals("heat map at " + x + ", " + y, 0, map.getRGB(x, y) & 0xffffff);
            }
        }
    }

    /** 100×100 pixels, one green channel off by 5: one pixel of 10000 differs, share 1e-4; mean 5/(3·10000). */
    @Test
    public void onePixelOffByFiveIsExactlyThatShare() {
        BufferedImage a = randomImage(100, 100, 2);
        BufferedImage b = copy(a);
        shift(b, 3, 7, 0, 5, 0);
        ImageDiff.Result r = ImageDiff.compare(a, b);
        assertEquals(5, r.maxDifference());
        assertEquals(1, r.differingPixels());
        assertEquals(1e-4, r.differingShare(), 1e-15);
        assertEquals(5.0 / 30000, r.meanDifference(), 1e-15);
        assertEquals(5, r.differenceAt(3, 7));
        assertEquals(0, r.differenceAt(7, 3));
        assertTrue("1e-4 is below MAX_SHARE " + ImageDiff.MAX_SHARE, r.passed());
    }

    /** The same single pixel in a 10×10 image is 1% of it, more than MAX_SHARE allows. */
    @Test
    public void onePixelOffInATinyImageIsTooLargeAShare() {
        BufferedImage a = randomImage(10, 10, 3);
        BufferedImage b = copy(a);
        shift(b, 9, 9, -5, 0, 0);
        ImageDiff.Result r = ImageDiff.compare(a, b);
        assertEquals(1, r.differingPixels());
        assertEquals(0.01, r.differingShare(), 1e-15);
        assertFalse(r.toString(), r.passed());
        assertTrue(r.toString(), r.toString().startsWith("FAIL: max 5, mean 0.017, 1 of 100 pixels (1.000%) differ by more than "
                + ImageDiff.TOLERANCE_LEVELS + " levels"));
    }

    @Test
    public void differencesUpToTheToleranceDoNotCountAndOneMoreLevelDoes() {
        int tolerance = ImageDiff.TOLERANCE_LEVELS;
        BufferedImage a = randomImage(30, 20, 4);
        BufferedImage within = copy(a);
        BufferedImage beyond = copy(a);
        for (int y = 0; y < 20; y++) {
            for (int x = 0; x < 30; x++) {
                shift(within, x, y, 0, 0, tolerance);
                shift(beyond, x, y, 0, 0, -(tolerance + 1));
            }
        }
        ImageDiff.Result r = ImageDiff.compare(a, within);
        assertEquals(tolerance, r.maxDifference());
        assertEquals(0, r.differingPixels());
        assertTrue(r.passed());
        // Only blue moved: the mean over three channels is a third of it.
        assertEquals(tolerance / 3.0, r.meanDifference(), 1e-12);

        r = ImageDiff.compare(a, beyond);
        assertEquals(tolerance + 1, r.maxDifference());
        assertEquals(600, r.differingPixels());
        assertFalse(r.passed());
    }

    /** (+2, +2, +2) is a difference of 2 (the largest channel), not 6 (their sum). */
    @Test
    public void aPixelsDifferenceIsItsLargestChannelDifference() {
        BufferedImage a = randomImage(8, 8, 5);
        BufferedImage b = copy(a);
        shift(b, 4, 4, 2, -2, 2);
        shift(b, 5, 5, 1, 7, -3);
        ImageDiff.Result r = ImageDiff.compare(a, b);
        assertEquals(2, r.differenceAt(4, 4));
        assertEquals(7, r.differenceAt(5, 5));
        assertEquals(7, r.maxDifference());
        assertEquals((6 + 11) / (3.0 * 64), r.meanDifference(), 1e-15);
    }

    /** 50×100 = 5000 pixels: the largest count MAX_SHARE allows passes, one more fails. */
    @Test
    public void verdictTurnsExactlyAtTheAllowedShare() {
        int n = 5000;
        int allowed = (int) Math.floor(ImageDiff.MAX_SHARE * n);
        assertTrue("the test needs MAX_SHARE to allow at least one pixel of " + n, allowed >= 1 && allowed < n);
        BufferedImage a = randomImage(50, 100, 6);
        BufferedImage b = copy(a);
        for (int k = 0; k < allowed; k++) {
            shift(b, k % 50, k / 50, 50, 0, 0);
        }
        assertTrue(ImageDiff.compare(a, b).passed());
        shift(b, 49, 99, 0, 0, -20);
        ImageDiff.Result r = ImageDiff.compare(a, b);
        assertEquals(allowed + 1, r.differingPixels());
        assertFalse(r.passed());
    }

    @Test
    public void differentSizesFailWithoutAnException() {
        ImageDiff.Result r = ImageDiff.compare(randomImage(4, 4, 7), randomImage(5, 4, 7));
        assertFalse(r.sameSize());
        assertFalse(r.passed());
        assertEquals(1.0, r.differingShare(), 0);
        assertEquals("the images differ in size: expected 4x4, actual 5x4", r.summary());
        assertTrue(r.toString().startsWith("FAIL"));
        assertThrows(IllegalStateException.class, r::heatMap);
        assertThrows(IllegalStateException.class, r::worstPixel);
    }

    @Test
    public void alphaIsIgnored() {
        BufferedImage a = randomImage(6, 6, 8);
        BufferedImage b = new BufferedImage(6, 6, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 6; y++) {
            for (int x = 0; x < 6; x++) {
                b.setRGB(x, y, (x * 40) << 24 | (a.getRGB(x, y) & 0xffffff));
            }
        }
        ImageDiff.Result r = ImageDiff.compare(a, b);
        assertEquals(0, r.maxDifference());
        assertTrue(r.passed());
    }

    /** Black for equal, pure blue within the tolerance, then dark red rising through yellow to white at 255. */
    @Test
    public void heatMapColorsFollowTheDifference() {
        int tolerance = ImageDiff.TOLERANCE_LEVELS;
        assertEquals(0, ImageDiff.heatColor(0, tolerance));
        for (int d = 1; d <= tolerance; d++) {
            int c = ImageDiff.heatColor(d, tolerance);
            assertEquals("within tolerance, only blue: " + Integer.toHexString(c), 0, c & 0xffff00);
            assertTrue(Integer.toHexString(c), (c & 255) >= 64);
        }
        int first = ImageDiff.heatColor(tolerance + 1, tolerance);
        assertTrue("just beyond the tolerance: dark red, got " + Integer.toHexString(first),
                (first >> 16) >= 128 && (first & 0xffff) == 0);
        assertEquals(0xffffff, ImageDiff.heatColor(255, tolerance));
        int previous = -1;
        for (int d = tolerance + 1; d <= 255; d++) {
            int c = ImageDiff.heatColor(d, tolerance);
            int brightness = (c >> 16 & 255) + (c >> 8 & 255) + (c & 255);
            assertTrue("brightness must not drop at " + d, brightness >= previous);
            previous = brightness;
        }
    }

    @Test
    public void heatMapMarksTheDifferingPixel() {
        BufferedImage a = randomImage(12, 9, 9);
        BufferedImage b = copy(a);
        shift(b, 2, 8, 0, -9, 0);
        shift(b, 11, 0, 1, 0, 0);
        BufferedImage map = ImageDiff.compare(a, b).heatMap();
        assertEquals(ImageDiff.heatColor(9, ImageDiff.TOLERANCE_LEVELS), map.getRGB(2, 8) & 0xffffff);
        assertEquals(ImageDiff.heatColor(1, ImageDiff.TOLERANCE_LEVELS), map.getRGB(11, 0) & 0xffffff);
        assertEquals(0, map.getRGB(0, 0) & 0xffffff);
    }

    /**
     * The mask of the pixels that count (beyond the tolerance, not at it), and the worst pixel: the
     * largest difference, the first in reading order from the top-left on a tie, as ray1 trace counts.
     */
    @Test
    public void differingPixelsAndTheWorstAreFoundWhereTheyAreCountedFromTheTop() {
        BufferedImage a = randomImage(12, 9, 10);
        BufferedImage b = copy(a);
        shift(b, 3, 7, 0, ImageDiff.TOLERANCE_LEVELS, 0);
        shift(b, 5, 1, 0, 0, ImageDiff.TOLERANCE_LEVELS + 1);
        shift(b, 10, 6, 9, 0, 0);
        shift(b, 2, 6, -9, 0, 0);
        shift(b, 7, 2, 0, 4, 0);
        ImageDiff.Result r = ImageDiff.compare(a, b);
        assertEquals(4, r.differingPixels());
        int counted = 0;
        for (int y = 0; y < 9; y++) {
            for (int x = 0; x < 12; x++) {
                assertEquals("(" + x + ", " + y + ")", r.differenceAt(x, y) > ImageDiff.TOLERANCE_LEVELS, r.differsAt(x, y));
                counted += r.differsAt(x, y) ? 1 : 0;
            }
        }
        assertEquals(4, counted);
        assertFalse("at the tolerance, not beyond it", r.differsAt(3, 7));
        assertTrue(r.differsAt(5, 1));
        assertEquals("9 levels at (2, 6) and (10, 6): the left one, read first", new ImageDiff.Pixel(2, 6), r.worstPixel());
        assertEquals("(2, 6)", r.worstPixel().toString());
        assertEquals(9, r.differenceAt(r.worstPixel().x(), r.worstPixel().y()));
        shift(b, 11, 0, 0, 0, 9);
        assertEquals("a tie in an earlier row wins", new ImageDiff.Pixel(11, 0), ImageDiff.compare(a, b).worstPixel());
        assertEquals("equal images: the first pixel", new ImageDiff.Pixel(0, 0), ImageDiff.compare(a, copy(a)).worstPixel());
    }
}
