package ray.image;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.Random;
import org.junit.Test;
import ray.math.Vec3;

/** The accuracy report's error measures, on images whose errors are known by construction. */
public class ImageErrorTest {
    private static Image constant(int w, int h, double value) {
        Image image = new Image(w, h);
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                image.set(i, j, new Vec3(value, value, value));
            }
        }
        return image;
    }

    @Test
    public void anImageAgainstItselfHasNoError() {
        Image image = new Image(5, 4);
        Random random = new Random(1);
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 5; i++) {
                image.set(i, j, new Vec3(random.nextDouble(), 3 * random.nextDouble(), random.nextDouble()));
            }
        }
        ImageError e = ImageError.of(image, image, 1);
        assertEquals(0, e.rmse, 0);
        assertEquals(0, e.maxError, 0);
        assertEquals(Double.POSITIVE_INFINITY, e.psnr, 0);
        assertEquals(0, e.visibleShare, 0);
    }

    @Test
    public void plusOrMinusDeltaEverywhereHasRmseDeltaAndItsPsnr() {
        // Channels alternate +δ and −δ around 0.25: every squared error is δ², so RMSE = max = δ
        // exactly, and PSNR = 20·log10(peak/δ) with peak = 1/exposure = 2.
        double delta = 0.01;
        Image reference = constant(6, 3, 0.25);
        Image noisy = new Image(6, 3);
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 6; i++) {
                double s = (i + j) % 2 == 0 ? delta : -delta;
                noisy.set(i, j, new Vec3(0.25 + s, 0.25 - s, 0.25 + s));
            }
        }
        ImageError e = ImageError.of(noisy, reference, 0.5);
        assertEquals(delta, e.rmse, 1e-15);
        assertEquals(delta, e.maxError, 1e-15);
        assertEquals(20 * Math.log10(2 / delta), e.psnr, 1e-9);
    }

    @Test
    public void seededGaussianNoiseHasItsStandardDeviationAsRmse() {
        // 300×200×3 = 180,000 samples of N(0, σ²): the sample RMSE is within 1% of σ (about 3 standard errors).
        double sigma = 0.02;
        Image reference = constant(300, 200, 0.5);
        Image noisy = new Image(300, 200);
        Random random = new Random(20261122);
        for (int j = 0; j < 200; j++) {
            for (int i = 0; i < 300; i++) {
                noisy.set(i, j, new Vec3(0.5 + sigma * random.nextGaussian(), 0.5 + sigma * random.nextGaussian(),
                        0.5 + sigma * random.nextGaussian()));
            }
        }
        ImageError e = ImageError.of(noisy, reference, 1);
        assertEquals(sigma, e.rmse, 0.01 * sigma);
        assertEquals(20 * Math.log10(1 / sigma), e.psnr, 0.1);
        assertTrue("the largest of 180,000 normal errors is beyond 4σ", e.maxError > 4 * sigma && e.maxError < 6 * sigma);
    }

    @Test
    public void aPixelIsVisiblyOffWhenItsDisplayValueMovesMoreThanOneStep() {
        // Display value d comes from radiance d^2.2 (exposure 1). Move one channel of one pixel of
        // four to d + 1.2/255 (visible) and another to d + 0.8/255 (not visible).
        double d = 0.5;
        Image reference = constant(2, 2, Math.pow(d, ToneMap.GAMMA));
        Image image = constant(2, 2, Math.pow(d, ToneMap.GAMMA));
        Vec3 r = reference.get(0, 0);
        image.set(0, 0, new Vec3(Math.pow(d + 1.2 / 255, ToneMap.GAMMA), r.y, r.z));
        image.set(1, 0, new Vec3(r.x, Math.pow(d + 0.8 / 255, ToneMap.GAMMA), r.z));
        assertEquals(0.25, ImageError.of(image, reference, 1).visibleShare, 0);
    }

    @Test
    public void nanCountsAsAnInfiniteAndVisibleError() {
        Image reference = constant(2, 1, 0.3);
        Image image = constant(2, 1, 0.3);
        image.set(1, 0, new Vec3(Double.NaN, 0.3, 0.3));
        ImageError e = ImageError.of(image, reference, 1);
        assertEquals(Double.POSITIVE_INFINITY, e.rmse, 0);
        assertEquals(Double.POSITIVE_INFINITY, e.maxError, 0);
        assertEquals(0.5, e.visibleShare, 0);
    }

    @Test
    public void imagesOfDifferentSizesCannotBeCompared() {
        try {
            ImageError.of(new Image(3, 2), new Image(2, 3), 1);
            fail("expected an exception");
        } catch (IllegalArgumentException e) {
            assertEquals("the image is 3x2 but the reference is 2x3", e.getMessage());
        }
    }
}
