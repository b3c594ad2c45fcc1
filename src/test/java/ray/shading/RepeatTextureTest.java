package ray.shading;

import static ray.shading.TextureLookups.assertTexel;

import org.junit.Test;
import ray.testing.Points;

/**
 * Checks RepeatTexture.getTexColor on a 4×3 image of distinct texels: column (int)(u·W + ½) and row
 * (int)((1 − v)·H + ½) from the top, wrapped into the image. Texel (column, row)'s center is at
 * u = column/W, v = 1 − row/H. The general cases keep at least 0.2 of a texel from any edge between
 * texels (see {@link TextureLookups} on what is accepted where); the edge cases are hand-computed.
 */
@Points(1)
public class RepeatTextureTest extends TextureLookupCases {
    private static final String RULE = "the texel is column (int)(u·W + 0.5) and row (int)((1 − v)·H + 0.5) counted from the"
            + " top (Math.floor instead of (int) is accepted too), each wrapped into 0…W−1 and 0…H−1 (Math.floorMod), read with"
            + " texel(column, row)";

    public RepeatTextureTest() {
        super(RULE, RepeatTexture::new, i -> Math.floorMod(i, W), r -> Math.floorMod(r, H));
    }

    /**
     * v = 0 is half a texel below the bottom row's center (v = 1/3 here): (int)((1 − 0)·3 + 0.5) = 3,
     * one past the last row, which wraps to row 0, the top. So under Repeat the image's bottom edge
     * reads its top row, as the course's renderer does; likewise u = 1 reads column 0.
     */
    @Test
    @Points(2)
    public void theImagesEdgesWrapAsTheCourseDoes() {
        assertTexel(RULE, texture, W, H, 0.0, 0.0, 0, 0);
        assertTexel(RULE, texture, W, H, 0.5, 0.0, 2, 0);
        assertTexel(RULE, texture, W, H, 1.0, 0.6, 0, 1); // u = 1: (int)(4.5) = column 4, wrapped to 0; row (int)(1.7)
        assertTexel(RULE, texture, W, H, 1.0, 1.0, 0, 0);
    }

    /** On a texel edge beyond the image too, the course flips v before rounding, then wraps. */
    @Override
    @Test
    public void onATexelEdgeTheCourseFlipsVBeforeRounding() {
        super.onATexelEdgeTheCourseFlipsVBeforeRounding();
        assertTexel(RULE, texture, W, H, 1.375, -0.5, 2, 2);
    }

    @Test
    public void coordinatesAboveOneWrapAround() {
        check(1.25, 0.9); // reads like u = 0.25: column 1; (int)(0.3 + 0.5) = row 0
        check(2.5, 1 + 2 / 3.0); // like (0.5, 2/3): texel (2, 1)
        check(0.97, 0.1); // column (int)(4.38) = 4, which wraps to 0; row (int)(3.2) = 3, which wraps to 0
        check(7.05, 5.3);
    }

    @Test
    @Points(2)
    public void negativeCoordinatesWrapIntoTheImage() {
        // Java's % keeps the sign: −1 % 4 is −1, not a column. Either nearest-texel rounding is accepted where they part.
        check(-0.25, 0.9);
        check(0.1, -0.6);
        check(-1.55, -2.25);
        check(-3.05, 1 / 3.0);
        check(0.3, 1.9); // (1 − 1.9)·3 + 0.5 = −2.2: a negative row before wrapping
    }
}
