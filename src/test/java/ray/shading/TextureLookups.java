package ray.shading;

import static org.junit.Assert.fail;

import java.util.Locale;
import java.util.function.IntUnaryOperator;
import ray.image.Image;
import ray.math.Vec3;
import ray.testing.Hints;

/**
 * What the lookup tests share: small images whose every texel has its own color, and a check that
 * accepts each texel a correct lookup may return. Texels are named as the lookups name them:
 * (column, row), the column from the image's left and the row from its top.
 *
 * <p>The course's rule is column (int)(u·W + ½) and row (int)((1 − v)·H + ½). Fairness: away from
 * the edges between texels every correct way of writing it agrees ((int) of it, Math.floor of it,
 * Math.round(u·W), wrapping u into [0, 1) first), so the general tests sample a fraction of a texel
 * from any edge. Where u·W + ½ &lt; 0, Java's (int) rounds toward zero and Math.floor down, one texel
 * apart; the course's reference uses (int), but both are correct nearest-texel rules, so both texels
 * are accepted there. The tests that sit exactly on an edge say so and use coordinates every form
 * computes exactly.
 */
final class TextureLookups {
    private TextureLookups() {
    }

    /** A W×H image whose texel (column, row) is {@link #texel texel(W, H, column, row)}: no two alike. */
    static Image distinctTexels(int width, int height) {
        Image image = new Image(width, height);
        for (int column = 0; column < width; column++) {
            for (int row = 0; row < height; row++) {
                // Image.set counts j from the bottom; the row counts from the top.
                image.set(column, height - 1 - row, texel(width, height, column, row));
            }
        }
        return image;
    }

    /** The color of texel (column, row), the row counted from the top, in a {@link #distinctTexels} image. */
    static Vec3 texel(int width, int height, int column, int row) {
        return new Vec3((double) column / width, (double) row / height, 0.5 + (column + row) / (2.0 * (width + height)));
    }

    /** The texel (column, row) whose color is {@code color} in a {@link #distinctTexels} image, or null. */
    static int[] whichTexel(int width, int height, Vec3 color) {
        for (int column = 0; column < width; column++) {
            for (int row = 0; row < height; row++) {
                if (texel(width, height, column, row).equals(color)) {
                    return new int[] {column, row};
                }
            }
        }
        return null;
    }

    /** The columns a correct rule may give for u on a side of n texels, before wrapping or clamping. */
    static int[] columns(double u, int n) {
        return candidates(u * n + 0.5);
    }

    /** The rows from the top a correct rule may give for v on a side of n texels, before wrapping or clamping. */
    static int[] rows(double v, int n) {
        return candidates((1 - v) * n + 0.5);
    }

    private static int[] candidates(double scaled) {
        int towardZero = (int) scaled;
        int down = (int) Math.floor(scaled);
        return towardZero == down ? new int[] {down} : new int[] {down, towardZero};
    }

    /**
     * Calls {@code check(u, v)} at every texel's center (u = column/W, v = 1 − row/H) and ±0.3 of a
     * texel around it in u and v, which still reads that texel.
     */
    static void nearEachTexelCenter(int width, int height, java.util.function.BiConsumer<Double, Double> check) {
        for (int column = 0; column < width; column++) {
            for (int row = 0; row < height; row++) {
                for (double du : new double[] {-0.3, 0, 0.3}) {
                    for (double dv : new double[] {-0.3, 0, 0.3}) {
                        check.accept((column + du) / width, 1 - (row + dv) / height);
                    }
                }
            }
        }
    }

    /**
     * Checks texture.getTexColor(u, v) on a distinctTexels(W, H) image: it must be texel (column, row)
     * for some column in {@code fixColumn(columns(u, W))} and row in {@code fixRow(rows(v, H))}.
     */
    static void assertLookup(String rule, Texture texture, int width, int height, double u, double v,
            IntUnaryOperator fixColumn, IntUnaryOperator fixRow) {
        StringBuilder expected = new StringBuilder();
        for (int i : columns(u, width)) {
            for (int r : rows(v, height)) {
                expected.append(expected.length() == 0 ? "" : " or ")
                        .append("(" + fixColumn.applyAsInt(i) + ", " + fixRow.applyAsInt(r) + ")");
            }
        }
        Vec3 got = lookUp(rule, texture, width, height, u, v);
        for (int i : columns(u, width)) {
            for (int r : rows(v, height)) {
                if (texel(width, height, fixColumn.applyAsInt(i), fixRow.applyAsInt(r)).equals(got)) {
                    return;
                }
            }
        }
        failWrongTexel(rule, texture, width, height, u, v, expected.toString(), got);
    }

    /** Checks that texture.getTexColor(u, v) is exactly texel (column, row) of a distinctTexels(W, H) image. */
    static void assertTexel(String rule, Texture texture, int width, int height, double u, double v, int column, int row) {
        Vec3 got = lookUp(rule, texture, width, height, u, v);
        if (!texel(width, height, column, row).equals(got)) {
            failWrongTexel(rule, texture, width, height, u, v, "(" + column + ", " + row + ")", got);
        }
    }

    private static Vec3 lookUp(String rule, Texture texture, int width, int height, double u, double v) {
        try {
            return texture.getTexColor(u, v);
        } catch (RuntimeException e) {
            fail(call(texture, width, height, u, v) + " threw " + e + "; " + rule);
            return null;
        }
    }

    private static void failWrongTexel(String rule, Texture texture, int width, int height, double u, double v, String expected,
            Vec3 got) {
        int[] actual = whichTexel(width, height, got);
        fail(call(texture, width, height, u, v) + " must return texel " + expected + " (column, row from the top), but returned "
                + (actual == null ? "the color " + got + ", which is no texel of the image"
                        : "texel (" + actual[0] + ", " + actual[1] + ")")
                + "; " + Hints.wordsOrFormula(inWords(rule), rule));
    }

    /**
     * A lookup's rule as the levels below {@code formulas} state it ({@link Hints}): the convention in
     * words, as the TODO states it at every level, without the formula or a worked case. The rules
     * name their edge handling ("wrapped", "clamped", "clamps"); anything after them is a worked case.
     */
    static String inWords(String rule) {
        return "the texel is the nearest one: column u·W and row (1 − v)·H counted from the top, each rounded to the nearest"
                + " whole number (halves up), then " + (rule.contains("clamp") ? "clamped to the image" : "wrapped into the image");
    }

    private static String call(Texture texture, int width, int height, double u, double v) {
        return String.format(Locale.ROOT, "%s.getTexColor(%s, %s) on a %d×%d image", texture.getClass().getSimpleName(), u, v,
                width, height);
    }
}
