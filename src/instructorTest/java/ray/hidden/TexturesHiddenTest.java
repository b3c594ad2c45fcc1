package ray.hidden;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.math.BigDecimal;
import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.image.Image;
import ray.math.Vec3;
import ray.shading.ClampTexture;
import ray.shading.RepeatTexture;
import ray.shading.Texture;
import ray.shading.TextureLookupsAccess;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden lookup cases: seeded images of every shape from 1×1 to 9×7 (one row, one column, wide,
 * tall) with coordinates from −3 to 3 kept 0.2 of a texel from any edge between texels; the image's
 * own edges (u and v of 0 and 1) and coordinates exactly on the edges between texels, hand-computed
 * on every shape up to 8×8; and the lookup as the shaders call it, through a hit's texture
 * coordinates. Texels are named (column, row), the row counted from the top.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class TexturesHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final int CASES = 400;

    /** A coordinate in [−3, 3] whose x·n + ½ is at least 0.2 from an integer. */
    private static double awayFromEdges(Random random, int n) {
        while (true) {
            double x = 6 * random.nextDouble() - 3;
            double scaled = x * n + 0.5;
            double fromEdge = Math.abs(scaled - Math.rint(scaled));
            if (fromEdge > 0.2) {
                return x;
            }
        }
    }

    private static void randomLookups(long seed, boolean repeat) {
        Random random = new Random(seed);
        for (int k = 0; k < CASES; k++) {
            int width = 1 + random.nextInt(9);
            int height = 1 + random.nextInt(7);
            Image image = TextureLookupsAccess.distinctTexels(width, height);
            Texture texture = repeat ? new RepeatTexture(image) : new ClampTexture(image);
            double u = awayFromEdges(random, width);
            double v = awayFromEdges(random, height);
            if (repeat) {
                TextureLookupsAccess.assertRepeat(texture, width, height, u, v);
            } else {
                TextureLookupsAccess.assertClamp(texture, width, height, u, v);
            }
        }
    }

    @Test
    @Points(value = 2, visibility = Visibility.HIDDEN)
    public void repeatOnImagesOfEveryShape() {
        randomLookups(5_000_001, true);
    }

    @Test
    @Points(value = 2, visibility = Visibility.HIDDEN)
    public void clampOnImagesOfEveryShape() {
        randomLookups(5_000_002, false);
    }

    /**
     * u and v of exactly 0 and 1 on every shape: u = 1 makes column W and v = 0 makes row
     * (int)(H + 0.5) = H, one past the last, so Repeat reads column 0 and row 0 there (all four
     * corners of [0, 1]² read the top-left texel) and Clamp the last column and the bottom row.
     */
    @Test
    @Points(value = 2, visibility = Visibility.HIDDEN)
    public void theImagesEdgesOnImagesOfEveryShape() {
        for (int width = 1; width <= 8; width++) {
            for (int height = 1; height <= 8; height++) {
                Image image = TextureLookupsAccess.distinctTexels(width, height);
                for (double u : new double[] {0, 1}) {
                    for (double v : new double[] {0, 1}) {
                        TextureLookupsAccess.assertTexel(new RepeatTexture(image), width, height, u, v, 0, 0);
                        TextureLookupsAccess.assertTexel(new ClampTexture(image), width, height, u, v, u == 0 ? 0 : width - 1,
                                v == 1 ? 0 : height - 1);
                    }
                }
            }
        }
    }

    /**
     * Coordinates exactly on the edge between two texels, wherever that edge is exact in binary on
     * a side of n ≤ 8 texels, shifted by whole tiles: u·W + 0.5 = m takes column m, and
     * (1 − v)·H + 0.5 = m takes row m from the top, the course's rule (flip v, then round), before
     * wrapping or clamping.
     */
    @Test
    public void coordinatesOnTexelEdgesRoundAsTheCourseDoes() {
        for (int width = 1; width <= 8; width++) {
            for (int height = 1; height <= 8; height++) {
                Image image = TextureLookupsAccess.distinctTexels(width, height);
                for (int m = 0; m <= width; m++) {
                    for (int k = 0; k <= height; k++) {
                        double u = (m - 0.5) / width;
                        double v = 1 - (k - 0.5) / height;
                        if (!exactlyOnEdge(u, width, m, false) || !exactlyOnEdge(v, height, k, true)) {
                            continue; // (m − ½)/n is not exact in binary: the ways of rounding may part before the edge
                        }
                        for (int tiles = -1; tiles <= 2; tiles++) {
                            int column = m + tiles * width;
                            int row = k - tiles * height;
                            TextureLookupsAccess.assertTexel(new RepeatTexture(image), width, height, u + tiles, v + tiles,
                                    Math.floorMod(column, width), Math.floorMod(row, height));
                            TextureLookupsAccess.assertTexel(new ClampTexture(image), width, height, u + tiles, v + tiles,
                                    Math.max(0, Math.min(width - 1, column)), Math.max(0, Math.min(height - 1, row)));
                        }
                    }
                }
            }
        }
    }

    /**
     * Whether x·n + ½ (or (1 − x)·n + ½ when {@code flipped}) is exactly m, in exact arithmetic on the
     * double x, shifted by each whole tile the test uses: only then does every correct form of the
     * lookup compute the same edge.
     */
    private static boolean exactlyOnEdge(double x, int n, int m, boolean flipped) {
        for (int tiles = -1; tiles <= 2; tiles++) {
            double shifted = x + tiles;
            BigDecimal exact = new BigDecimal(shifted);
            BigDecimal coordinate = flipped ? BigDecimal.ONE.subtract(exact) : exact;
            BigDecimal expected = BigDecimal.valueOf(flipped ? m - (long) tiles * n : m + (long) tiles * n);
            if (new BigDecimal(shifted - tiles).compareTo(new BigDecimal(x)) != 0
                    || coordinate.multiply(BigDecimal.valueOf(n)).add(new BigDecimal("0.5")).compareTo(expected) != 0) {
                return false;
            }
        }
        return true;
    }

    @Test
    public void aOneTexelImageIsOneColorEverywhere() {
        Image one = new Image(1, 1);
        Vec3 color = new Vec3(0.2, 0.4, 0.6);
        one.set(0, 0, color);
        for (double u : new double[] {-2.3, -0.4, 0, 0.3, 0.9, 1.7, 12.2}) {
            assertEquals("RepeatTexture on a 1×1 image at u = v = " + u, color, new RepeatTexture(one).getTexColor(u, u));
            assertEquals("ClampTexture on a 1×1 image at u = v = " + u, color, new ClampTexture(one).getTexColor(u, u));
        }
    }

    @Test
    public void shadersLookUpTheHitsTextureCoordinates() {
        // Texture.colorAt(hit) passes the hit's (u, v), rounded to float as the course does, to getTexColor.
        Image image = TextureLookupsAccess.distinctTexels(8, 4);
        IntersectionRecord hit = new IntersectionRecord();
        hit.texU = 0.625; // column 5's center: 0.625·8 + 0.5 = 5.5
        hit.texV = 0.25; // row 3's center, counted from the top: (1 − 0.25)·4 + 0.5 = 3.5
        Vec3 expected = TextureLookupsAccess.texel(8, 4, 5, 3);
        assertEquals("RepeatTexture.colorAt a hit with (u, v) = (0.625, 0.25) on an 8×4 image: texel (5, 3), the row from the top",
                expected, new RepeatTexture(image).colorAt(hit));
        assertEquals("ClampTexture.colorAt the same hit", expected, new ClampTexture(image).colorAt(hit));
        hit.texU = 1.625;
        hit.texV = -2.75; // (1 + 2.75)·4 + 0.5 = 15.5: row 15, which wraps to 3
        assertEquals("RepeatTexture.colorAt (1.625, −2.75): texel (5, 3) again", expected, new RepeatTexture(image).colorAt(hit));
        assertTrue("ClampTexture.colorAt (1.625, −2.75): the bottom-right texel (7, 3)",
                TextureLookupsAccess.texel(8, 4, 7, 3).equals(new ClampTexture(image).colorAt(hit)));
    }
}
