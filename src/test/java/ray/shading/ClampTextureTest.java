package ray.shading;

import static ray.shading.TextureLookups.assertLookup;
import static ray.shading.TextureLookups.assertTexel;
import static ray.shading.TextureLookups.nearEachTexelCenter;

import org.junit.Rule;
import org.junit.Test;
import ray.image.Image;
import ray.testing.Points;
import ray.testing.StudentTask;
import ray.testing.StudentTaskRule;

/**
 * Checks ClampTexture.getTexColor on a 4×3 image of distinct texels: column (int)(u·W + ½) and row
 * (int)((1 − v)·H + ½) from the top, clamped to the image, so beyond [0, 1] the edge texels extend.
 * General points inside are at least 0.2 of a texel from an edge between texels; the edge cases are
 * hand-computed.
 */
@Points(value = 1, task = StudentTask.TEXTURE)
public class ClampTextureTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.TEXTURE);

    private static final int W = 4;
    private static final int H = 3;
    private static final String RULE = "the texel is column (int)(u·W + 0.5) and row (int)((1 − v)·H + 0.5) counted from the"
            + " top (Math.floor instead of (int) is accepted too), each clamped to 0…W−1 and 0…H−1, read with texel(column, row)";
    private final Image image = TextureLookups.distinctTexels(W, H);
    private final ClampTexture texture = new ClampTexture(image);

    private void check(double u, double v) {
        assertLookup(RULE, texture, W, H, u, v, i -> Math.max(0, Math.min(W - 1, i)), r -> Math.max(0, Math.min(H - 1, r)));
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE)
    public void eachTexelIsReadNearItsCenter() {
        // Texel (column, row)'s center is at u = column/W, v = 1 − row/H; ±0.3 of a texel still reads it.
        nearEachTexelCenter(W, H, this::check);
    }

    @Test
    public void rowsCountFromTheTopAndVFromTheBottom() {
        assertTexel(RULE, texture, W, H, 0.0, 1.0, 0, 0); // v = 1: row 0, the top-left texel
        assertTexel(RULE, texture, W, H, 0.75, 1.0, 3, 0);
        check(0.0, 1 / 3.0); // row 2, the bottom row
        check(0.5, 2 / 3.0);
    }

    /**
     * v = 0 gives row (int)(3.5) = 3, one past the last, clamped to row 2, the bottom (where Repeat
     * wraps to the top); u = 1 gives column 4, clamped to 3.
     */
    @Test
    @Points(value = 2, task = StudentTask.TEXTURE)
    public void theImagesEdgesClampAsTheCourseDoes() {
        assertTexel(RULE, texture, W, H, 0.0, 0.0, 0, 2);
        assertTexel(RULE, texture, W, H, 1.0, 0.0, 3, 2);
        assertTexel(RULE, texture, W, H, 1.0, 1.0, 3, 0);
    }

    /** Exactly on the edges between texels, as in RepeatTextureTest: flip v, then round. */
    @Test
    public void onATexelEdgeTheCourseFlipsVBeforeRounding() {
        assertTexel(RULE + "; v = 0.5 lies on the edge between rows 1 and 2, and (int)((1 − 0.5)·3 + 0.5) = 2 (flip v, then"
                + " round), not H − (int)(0.5·3 + 0.5) = 1 (round, then flip)", texture, W, H, 0.375, 0.5, 2, 2);
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE)
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
