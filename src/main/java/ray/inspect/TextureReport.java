package ray.inspect;

import java.io.PrintWriter;
import ray.IntersectionRecord;
import ray.assignment.Assignment;
import ray.image.Image;
import ray.math.Vec3;
import ray.shading.TexelPick;
import ray.shading.Texture;
import ray.surface.SurfaceKind;

/**
 * The texture lookup at a hit of a textured shader: the hit's (u, v), the texel the course's
 * convention picks for them (column (int) (u·W + ½), row (int) ((1 − v)·H + ½) counted from the
 * top, as {@link Texture} says), and the color the texture returns, which replaces kd. Where that
 * column and row lie inside the image, the texel is the same for Repeat and Clamp and for every
 * correct way of rounding, so a lookup that returns another color is flagged, and the texel it
 * read is named by its index ({@link TexelPick}); outside, the trace says what wrapping or clamping
 * must do, shows the texel the lookup read, and leaves the verdict to the reader.
 */
final class TextureReport {
    private TextureReport() {
    }

    /** Prints the lookup: the hit's (u, v), the texel they pick and the kd the texture gives there. */
    static void explain(Texture texture, IntersectionRecord hit, String in, PrintWriter out) {
        Image image = texture.getImage();
        int w = image.width();
        int h = image.height();
        // The lookup takes float coordinates (FrameworkTexture.colorAt), so the texel follows from these.
        float u = (float) hit.texU;
        float v = (float) hit.texV;
        out.println(Fmt.row(in, "texture", texture + ", whose color at (u, v) replaces kd"));
        out.println(Fmt.row(in, "(u, v)", "(" + Fmt.num(hit.texU) + ", " + Fmt.num(hit.texV) + ")   (the hit's texture coordinates"
                + (hit.surface == null ? "" : ", set by " + hit.surface.getClass().getSimpleName() + ".intersect") + ")"));
        if (hit.texU == 0 && hit.texV == 0 && SurfaceKind.of(hit.surface) == SurfaceKind.SPHERE) {
            out.println(Fmt.row(in, "!", "(0, 0) is the sphere's south pole: does Sphere.intersect set texU and texV? See " + Assignment.current().todo("sphere")));
        }
        double columnAt = (double) u * w + 0.5; // in double, as getTexColor(double, double) computes it
        double rowAt = (1 - (double) v) * h + 0.5;
        int column = (int) columnAt;
        int row = (int) rowAt;
        String where = "column (int) (u·" + w + " + ½) = (int) " + Fmt.num(columnAt) + ", row (int) ((1 − v)·" + h + " + ½) = (int) "
                + Fmt.num(rowAt);
        Vec3 kd = texture.colorAt(hit);
        if (columnAt >= 0 && columnAt < w && rowAt >= 0 && rowAt < h) {
            Vec3 texel = texelFromTop(image, column, row);
            out.println(Fmt.row(in, "texel", "(" + column + ", " + row + ") of " + w + "×" + h + "   (" + where
                    + "; rows count from the image file's top)"));
            out.println(Fmt.row(in, "its color", Fmt.rgb8(eightBit(texel)) + " in the file, / 255 = " + Fmt.vec(texel)));
            if (!kd.equals(texel)) {
                out.println(Fmt.row(in, "!", texture.getClass().getSimpleName() + ".getTexColor returned " + Fmt.vec(kd)
                        + ", not that texel's color: " + whichTexel(TexelPick.of(texture, u, v), u, v, w, h, column, row, kd)
                        + " See " + Assignment.current().todo("textures")));
            }
        } else {
            out.println(Fmt.row(in, "texel", "(" + column + ", " + row + ") before it is"
                    + " brought into the " + w + "×" + h + " image (" + where + "): a RepeatTexture wraps it, a ClampTexture clamps it"));
            int[] picked = TexelPick.of(texture, u, v);
            if (picked != null) {
                out.println(Fmt.row(in, "read", "texel (" + picked[0] + ", " + picked[1] + ")   (the one "
                        + texture.getClass().getSimpleName() + ".getTexColor reads there)"));
            }
        }
        out.println(Fmt.row(in, "kd", Fmt.vec(kd) + "   (" + texture.getClass().getSimpleName() + ".getTexColor(u, v))"));
    }

    /**
     * Which texel a wrong lookup read, by its index ({@link TexelPick}: the lookup asked again on an
     * image whose texels are their own addresses), named by the mistake that reads it: each wrong
     * form students write is computed from the same (u, v) and compared by column and row, the most
     * specific first, so a texel that two forms explain is named by the first. {@code picked} is
     * null when the lookup returns no texel at all (the stub's black, a color it made up).
     */
    static String whichTexel(int[] picked, float u, float v, int w, int h, int column, int row, Vec3 kd) {
        if (picked == null) {
            return kd.equals(Vec3.ZERO) ? "black, which this texel is not: is it still the stub?"
                    : "that is no texel of the image: return texel(column, row) as it is.";
        }
        int c = picked[0];
        int r = picked[1];
        String that = "that is texel (" + c + ", " + r + "), ";
        if (c == column && r == h - 1 - (int) ((double) v * h + 0.5) && r != row) {
            return that + rowsAway(r - row) + ": flipping after the rounding, H − 1 − (int) (v·H + ½), is one row off"
                    + " everywhere; turn v into 1 − v first, then scale and round: (int) ((1 − v)·H + ½).";
        }
        if (c == column && r == h - 1 - row) {
            return that + "the same column in the mirrored row: are the rows flipped? Row 0 is the top of the image file,"
                    + " and v = 1 is the top of the texture (image.get counts rows from the bottom, texel(column, row) from the top).";
        }
        if (c == column && r == (int) ((double) v * h + 0.5)) {
            return that + rowsAway(r - row) + ", near the mirrored row: (int) (v·H + ½) counts rows from the bottom, and"
                    + " texel(column, row) counts them from the top; the row is (int) ((1 − v)·H + ½).";
        }
        if (r == row && c == w - 1 - column) {
            return that + "the same row in the mirrored column: column 0 is the image's left edge, where u = 0.";
        }
        if (c == (int) ((double) u * w) && r == (int) ((1 - (double) v) * h) && (c != column || r != row)) {
            return that + "the one whose corner, not its center, is at (u, v): add ½ before the cast,"
                    + " (int) (u·W + ½) and (int) ((1 − v)·H + ½).";
        }
        if (Math.abs(c - column) + Math.abs(r - row) == 1) {
            return "that is the neighbouring texel (" + c + ", " + r + "), " + (r != row ? rowsAway(r - row) : columnsAway(c - column))
                    + ": is u·W or (1 − v)·H rounded another way (add ½, then cast, once)?";
        }
        return that + (r != row ? rowsAway(r - row) + (c != column ? " and " + columnsAway(c - column) : "") : columnsAway(c - column))
                + " of the right one.";
    }

    /** "one row above" (toward the file's top) or "3 rows below", for a row offset ≠ 0. */
    private static String rowsAway(int offset) {
        int n = Math.abs(offset);
        return (n == 1 ? "one row " : n + " rows ") + (offset < 0 ? "above" : "below");
    }

    /** "one column to the left" or "2 columns to the right", for a column offset ≠ 0. */
    private static String columnsAway(int offset) {
        int n = Math.abs(offset);
        return (n == 1 ? "one column " : n + " columns ") + (offset < 0 ? "to the left" : "to the right");
    }

    /** Texel (column, row), the row counted from the top of the file (image.get counts from the bottom). */
    private static Vec3 texelFromTop(Image image, int column, int row) {
        return image.get(column, image.height() - 1 - row);
    }

    /** A texel's 8-bit color: texels are the file's values / 255, so this is exact. */
    private static int[] eightBit(Vec3 texel) {
        return new int[] {(int) Math.round(texel.x * 255), (int) Math.round(texel.y * 255), (int) Math.round(texel.z * 255)};
    }
}
