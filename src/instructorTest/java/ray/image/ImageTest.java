package ray.image;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.math.Vec3;

/** Image stores one color per pixel (i from the left, j from the bottom) and refuses pixels outside it. */
public class ImageTest {

    @Test
    public void newImageIsBlack() {
        Image image = new Image(3, 2);
        assertEquals(3, image.width());
        assertEquals(2, image.height());
        for (int j = 0; j < 2; j++) {
            for (int i = 0; i < 3; i++) {
                assertVec(Vec3.ZERO, image.get(i, j), 0);
            }
        }
    }

    @Test
    public void everyPixelKeepsItsOwnColorInANonSquareImage() {
        // Distinct values in every pixel and channel catch swapped or overlapping indices.
        Image image = new Image(5, 3);
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 5; i++) {
                image.set(i, j, v(i, j, 10 * i + j + 0.5));
            }
        }
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 5; i++) {
                assertVec("pixel (" + i + ", " + j + ")", v(i, j, 10 * i + j + 0.5), image.get(i, j), 0);
            }
        }
    }

    @Test
    public void setOverwritesAndGetReturnsACopy() {
        Image image = new Image(2, 2);
        image.set(1, 1, v(1, 2, 3));
        image.set(1, 1, v(-4, 5.5, 1e300));
        assertVec(v(-4, 5.5, 1e300), image.get(1, 1), 0);
        assertVec("neighbours untouched", Vec3.ZERO, image.get(0, 1), 0);
    }

    @Test
    public void pixelsOutsideTheImageAreRejected() {
        Image image = new Image(4, 3);
        int[][] outside = {{-1, 0}, {0, -1}, {4, 0}, {0, 3}, {4, 3}, {3, 3}, {4, 2}};
        for (int[] p : outside) {
            try {
                image.get(p[0], p[1]);
                fail("get(" + p[0] + ", " + p[1] + ") should be out of bounds");
            } catch (IndexOutOfBoundsException expected) {
                // the message names the pixel
            }
            try {
                image.set(p[0], p[1], Vec3.ONE);
                fail("set(" + p[0] + ", " + p[1] + ") should be out of bounds");
            } catch (IndexOutOfBoundsException expected) {
                // nothing written
            }
        }
        // The corners inside are fine.
        image.set(3, 2, Vec3.ONE);
        image.set(0, 0, Vec3.ONE);
        assertVec(Vec3.ONE, image.get(3, 2), 0);
    }

    @Test(expected = IllegalArgumentException.class)
    public void zeroWidthIsRejected() {
        new Image(0, 5);
    }

    @Test(expected = IllegalArgumentException.class)
    public void negativeHeightIsRejected() {
        new Image(5, -1);
    }
}
