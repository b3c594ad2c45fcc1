package ray.shading;

import static ray.shading.TextureLookups.assertLookup;

import org.junit.Rule;
import org.junit.Test;
import ray.image.Image;
import ray.testing.Points;
import ray.testing.StudentTask;
import ray.testing.StudentTaskRule;

/**
 * Checks RepeatTexture.getTexColor on a 4×3 image of distinct texels: the nearest texel
 * i = (int)(u·W + ½), j = (int)(v·H + ½), wrapped into the image. Every point is at least 0.2 of a
 * texel from an edge between texels (see {@link TextureLookups} on what is accepted where).
 */
@Points(value = 1, task = StudentTask.TEXTURE)
public class RepeatTextureTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.TEXTURE);

    private static final int W = 4;
    private static final int H = 3;
    private static final String RULE = "the nearest texel is i = (int)(u·W + 0.5), j = (int)(v·H + 0.5), wrapped into"
            + " 0…W−1 and 0…H−1 (Math.floorMod), and image.get(i, j) counts j from the bottom";
    private final Image image = TextureLookups.distinctTexels(W, H);
    private final RepeatTexture texture = new RepeatTexture(image);

    private void check(double u, double v) {
        assertLookup(RULE, texture, W, H, u, v, i -> Math.floorMod(i, W), j -> Math.floorMod(j, H));
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE)
    public void eachTexelIsReadNearItsCenter() {
        // Texel (i, j)'s center is at u = i/W, v = j/H; ±0.3 of a texel still reads it.
        for (int i = 0; i < W; i++) {
            for (int j = 0; j < H; j++) {
                for (double du : new double[] {-0.3, 0, 0.3}) {
                    for (double dv : new double[] {-0.3, 0, 0.3}) {
                        check((i + du) / W, (j + dv) / H);
                    }
                }
            }
        }
    }

    @Test
    public void vCountsRowsFromTheBottomAndUColumnsFromTheLeft() {
        check(0.0, 0.0); // texel (0, 0): the bottom-left
        check(0.75, 0.0); // (3, 0): the bottom-right
        check(0.0, 2 / 3.0); // (0, 2): the top-left
        check(0.5, 1 / 3.0); // (2, 1)
    }

    @Test
    public void coordinatesAboveOneWrapAround() {
        check(1.25, 0.1); // reads like u = 0.25: column 1
        check(2.5, 1 + 2 / 3.0); // like (0.5, 2/3): texel (2, 2)
        check(0.97, 0.9); // u·W + ½ = 4.38 → column 4, which wraps to 0; v: row 3 → 0
        check(7.05, 5.3);
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE)
    public void negativeCoordinatesWrapIntoTheImage() {
        // Java's % keeps the sign: −1 % 4 is −1, not a column. Either nearest-texel rounding is accepted here.
        check(-0.25, 0.1);
        check(0.1, -0.6);
        check(-1.55, -2.25);
        check(-3.05, 1 / 3.0);
    }
}
