package ray.shading;

import static ray.shading.TextureLookups.assertLookup;
import static ray.shading.TextureLookups.assertTexel;
import static ray.shading.TextureLookups.nearEachTexelCenter;

import java.util.function.Function;
import java.util.function.IntUnaryOperator;
import org.junit.Rule;
import org.junit.Test;
import ray.image.Image;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * What both texture lookups do inside the image, where they agree (ClampTextureTest and
 * RepeatTextureTest add what each does beyond it). The image is 4×3 texels of distinct colors;
 * texel (column, row)'s center is at u = column/W, v = 1 − row/H, and rows count from the top.
 */
public abstract class TextureLookupCases {
    static final int W = 4;
    static final int H = 3;

    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /** The lookup's rule, as a failure message states it. */
    final String rule;
    final Texture texture;
    private final IntUnaryOperator fixColumn;
    private final IntUnaryOperator fixRow;

    /**
     * @param fixColumn what the texture does with a column outside 0…W−1 (clamps it, wraps it)
     * @param fixRow    the same for a row outside 0…H−1
     */
    TextureLookupCases(String rule, Function<Image, Texture> texture, IntUnaryOperator fixColumn, IntUnaryOperator fixRow) {
        this.rule = rule;
        this.texture = texture.apply(TextureLookups.distinctTexels(W, H));
        this.fixColumn = fixColumn;
        this.fixRow = fixRow;
    }

    /** Checks the lookup at (u, v) against the rule (on an edge between texels either neighbor is accepted). */
    void check(double u, double v) {
        assertLookup(rule, texture, W, H, u, v, fixColumn, fixRow);
    }

    @Test
    @Points(2)
    public void eachTexelIsReadNearItsCenter() {
        // Texel (column, row)'s center is at u = column/W, v = 1 − row/H; ±0.3 of a texel still reads it.
        nearEachTexelCenter(W, H, this::check);
    }

    @Test
    public void rowsCountFromTheTopAndVFromTheBottom() {
        assertTexel(rule, texture, W, H, 0.0, 1.0, 0, 0); // v = 1: (int)(0·3 + 0.5) = row 0, the top-left texel
        assertTexel(rule, texture, W, H, 0.75, 1.0, 3, 0); // the top-right texel
        check(0.0, 1 / 3.0); // (int)((2/3)·3 + 0.5) = (int) 2.5: row 2, the bottom row
        check(0.5, 2 / 3.0); // (int)(1 + 0.5): column 2, row 1
    }

    /**
     * Exactly on the edges between texels, where two ways of rounding part: u = 0.375 makes
     * u·4 + 0.5 = 2 and v = 0.5 makes (1 − v)·3 + 0.5 = 2, both exact in binary. The course takes
     * column 2 and row 2, the lower of the two rows the edge separates, because it turns v into
     * 1 − v before rounding. Rounding v·3 + 0.5 = 2 first and flipping to H − 2 gives row 1: that
     * agrees everywhere but on such edges, where the reference images differ (a mesh whose vt sit on
     * texel edges shows it).
     */
    @Test
    public void onATexelEdgeTheCourseFlipsVBeforeRounding() {
        assertTexel(rule + "; v = 0.5 lies on the edge between rows 1 and 2, and (int)((1 − 0.5)·3 + 0.5) = 2 (flip v, then"
                + " round), not H − (int)(0.5·3 + 0.5) = 1 (round, then flip: that form agrees with the course's except on such"
                + " edges, and H − 1 − (int)(v·H + 0.5) is one row off everywhere)", texture, W, H, 0.375, 0.5, 2, 2);
    }
}
