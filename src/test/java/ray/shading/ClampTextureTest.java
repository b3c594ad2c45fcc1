package ray.shading;

import static ray.shading.TextureLookups.assertLookup;

import org.junit.Rule;
import org.junit.Test;
import ray.image.Image;
import ray.testing.Points;
import ray.testing.StudentTask;
import ray.testing.StudentTaskRule;

/**
 * Checks ClampTexture.getTexColor on a 4×3 image of distinct texels: the nearest texel
 * i = (int)(u·W + ½), j = (int)(v·H + ½), clamped to the image, so beyond [0, 1] the edge texels
 * extend. Points inside are at least 0.2 of a texel from an edge between texels.
 */
@Points(value = 1, task = StudentTask.TEXTURE)
public class ClampTextureTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.TEXTURE);

    private static final int W = 4;
    private static final int H = 3;
    private static final String RULE = "the nearest texel is i = (int)(u·W + 0.5), j = (int)(v·H + 0.5), clamped to"
            + " 0…W−1 and 0…H−1, and image.get(i, j) counts j from the bottom";
    private final Image image = TextureLookups.distinctTexels(W, H);
    private final ClampTexture texture = new ClampTexture(image);

    private void check(double u, double v) {
        assertLookup(RULE, texture, W, H, u, v, i -> Math.max(0, Math.min(W - 1, i)), j -> Math.max(0, Math.min(H - 1, j)));
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE)
    public void eachTexelIsReadNearItsCenter() {
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
        check(0.0, 0.0);
        check(0.75, 0.0);
        check(0.0, 2 / 3.0);
        check(0.5, 1 / 3.0);
    }

    @Test
    @Points(value = 2, task = StudentTask.TEXTURE)
    public void coordinatesBeyondTheImageReadItsEdge() {
        check(1.0, 0.4); // u·W + ½ = 4.5 → column 4, clamped to 3 (not wrapped to 0)
        check(0.97, 0.97); // column 4 and row 3, both one past the last: the top-right texel
        check(1.6, 0.1);
        check(0.45, 2.5); // the top row
        check(25, 40);
        check(-0.5, 0.4); // the left column
        check(0.55, -3); // the bottom row
        check(-7, -7); // the bottom-left texel
    }
}
