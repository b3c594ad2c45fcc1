package ray.shading;

import static org.junit.Assert.fail;

import java.util.Locale;
import java.util.function.IntUnaryOperator;
import ray.image.Image;
import ray.math.Vec3;

/**
 * What the lookup tests share: small images whose every texel has its own color, and a check that
 * accepts each texel a correct lookup may return.
 *
 * <p>Fairness: the nearest texel to u is column u·W + ½ rounded down. For u·W + ½ ≥ 0 every correct
 * form agrees ((int) of it, Math.floor of it, Math.round(u·W), wrapping u into [0, 1) first), as long
 * as the point is away from a texel's edge, so tests sample a fraction of a texel from any edge. For
 * u·W + ½ &lt; 0, Java's (int) rounds toward zero and Math.floor down, one texel apart; the course's
 * reference uses (int), but both are correct nearest-texel rules, so both texels are accepted there.
 */
final class TextureLookups {
    private TextureLookups() {
    }

    /** A W×H image whose texel (i, j) is (i/W, j/H, ½ + (i + j)/(2(W + H))): no two alike. */
    static Image distinctTexels(int width, int height) {
        Image image = new Image(width, height);
        for (int i = 0; i < width; i++) {
            for (int j = 0; j < height; j++) {
                image.set(i, j, texel(width, height, i, j));
            }
        }
        return image;
    }

    static Vec3 texel(int width, int height, int i, int j) {
        return new Vec3((double) i / width, (double) j / height, 0.5 + (i + j) / (2.0 * (width + height)));
    }

    /** The texel (i, j) whose color is {@code color} in a {@link #distinctTexels} image, or null. */
    static int[] whichTexel(int width, int height, Vec3 color) {
        for (int i = 0; i < width; i++) {
            for (int j = 0; j < height; j++) {
                if (texel(width, height, i, j).equals(color)) {
                    return new int[] {i, j};
                }
            }
        }
        return null;
    }

    /** The columns a correct nearest-texel rule may give for coordinate x on a side of n texels, before wrapping or clamping. */
    static int[] candidates(double x, int n) {
        double scaled = x * n + 0.5;
        int towardZero = (int) scaled;
        int down = (int) Math.floor(scaled);
        return towardZero == down ? new int[] {down} : new int[] {down, towardZero};
    }

    /**
     * Checks texture.getTexColor(u, v) on a distinctTexels(W, H) image: it must be texel (i, j) for
     * some i in {@code fix(candidates(u, W))} and j in {@code fix(candidates(v, H))}.
     */
    static void assertLookup(String rule, Texture texture, int width, int height, double u, double v,
            IntUnaryOperator fixColumn, IntUnaryOperator fixRow) {
        String call = String.format(Locale.ROOT, "%s.getTexColor(%s, %s) on a %d×%d image", texture.getClass().getSimpleName(),
                u, v, width, height);
        Vec3 got;
        try {
            got = texture.getTexColor(u, v);
        } catch (RuntimeException e) {
            fail(call + " threw " + e + "; " + rule);
            return;
        }
        StringBuilder expected = new StringBuilder();
        for (int i : candidates(u, width)) {
            for (int j : candidates(v, height)) {
                int column = fixColumn.applyAsInt(i);
                int row = fixRow.applyAsInt(j);
                if (texel(width, height, column, row).equals(got)) {
                    return;
                }
                expected.append(expected.length() == 0 ? "" : " or ").append("(" + column + ", " + row + ")");
            }
        }
        int[] actual = whichTexel(width, height, got);
        fail(call + " must return texel " + expected + " (j counted from the bottom row), but returned "
                + (actual == null ? "the color " + got + ", which is no texel of the image"
                        : "texel (" + actual[0] + ", " + actual[1] + ")")
                + "; " + rule);
    }
}
