package ray.shading;

import static ray.shading.TextureLookups.assertTexel;

import org.junit.Test;
import ray.testing.Points;

/**
 * Checks ClampTexture.getTexColor on a 4×3 image of distinct texels: column (int)(u·W + ½) and row
 * (int)((1 − v)·H + ½) from the top, clamped to the image, so beyond [0, 1] the edge texels extend.
 * General points inside are at least 0.2 of a texel from an edge between texels; the edge cases are
 * hand-computed. What it does inside the image, as RepeatTexture does: {@link TextureLookupCases}.
 */
@Points(1)
public class ClampTextureTest extends TextureLookupCases {
    private static final String RULE = "the texel is column (int)(u·W + 0.5) and row (int)((1 − v)·H + 0.5) counted from the"
            + " top (Math.floor instead of (int) is accepted too), each clamped to 0…W−1 and 0…H−1, read with texel(column, row)";

    public ClampTextureTest() {
        super(RULE, ClampTexture::new, i -> Math.max(0, Math.min(W - 1, i)), r -> Math.max(0, Math.min(H - 1, r)));
    }

    /**
     * v = 0 gives row (int)(3.5) = 3, one past the last, clamped to row 2, the bottom (where Repeat
     * wraps to the top); u = 1 gives column 4, clamped to 3.
     */
    @Test
    @Points(2)
    public void theImagesEdgesClampAsTheCourseDoes() {
        assertTexel(RULE, texture, W, H, 0.0, 0.0, 0, 2);
        assertTexel(RULE, texture, W, H, 1.0, 0.0, 3, 2);
        assertTexel(RULE, texture, W, H, 1.0, 1.0, 3, 0);
    }

    @Test
    @Points(2)
    public void coordinatesBeyondTheImageReadItsEdge() {
        check(1.0, 0.4); // u·W + ½ = 4.5 → column 4, clamped to 3 (not wrapped to 0)
        check(0.97, 0.03); // column 4 and row 3, both one past the last: the bottom-right texel
        check(1.6, 0.9);
        check(0.45, 2.5); // the top row
        check(25, 40);
        check(-0.5, 0.4); // the left column
        check(0.55, -3); // the bottom row
        check(-7, -7); // the bottom-left texel
    }
}
