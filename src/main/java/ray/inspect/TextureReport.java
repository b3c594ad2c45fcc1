package ray.inspect;

import java.io.PrintWriter;
import ray.IntersectionRecord;
import ray.image.Image;
import ray.math.Vec3;
import ray.shading.Texture;
import ray.surface.SurfaceKind;

/**
 * The texture lookup at a hit of a textured shader: the hit's (u, v), the texel the course's
 * convention picks for them (column (int) (u·W + ½), row (int) ((1 − v)·H + ½) counted from the
 * top, as {@link Texture} says), and the color the texture returns, which replaces kd. Where that
 * column and row lie inside the image, the texel is the same for Repeat and Clamp and for every
 * correct way of rounding, so a lookup that returns another color is flagged; outside, the trace
 * says what wrapping or clamping must do and leaves the answer to the texture.
 */
final class TextureReport {
    private TextureReport() {
    }

    /** Prints the lookup: the hit's (u, v), the texel they pick and the kd the texture gives there. */
    static void explain(Texture texture, IntersectionRecord hit, String in, PrintWriter out) {
        Image image = texture.getImage();
        int w = image.width();
        int h = image.height();
        // The lookup takes float coordinates (Texture.colorAt), so the texel follows from these.
        float u = (float) hit.texU;
        float v = (float) hit.texV;
        out.println(Fmt.row(in, "texture", texture + ", whose color at (u, v) replaces kd"));
        out.println(Fmt.row(in, "(u, v)", "(" + Fmt.num(hit.texU) + ", " + Fmt.num(hit.texV) + ")   (the hit's texture coordinates"
                + (hit.surface == null ? "" : ", set by " + hit.surface.getClass().getSimpleName() + ".intersect") + ")"));
        if (hit.texU == 0 && hit.texV == 0 && SurfaceKind.of(hit.surface) == SurfaceKind.SPHERE) {
            out.println(Fmt.row(in, "!", "(0, 0) is the sphere's south pole: does Sphere.intersect set texU and texV? See TODO(Task 2)"));
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
                        + ", not that texel's color: " + whichTexel(image, column, row, kd) + " See TODO(Task 5)"));
            }
        } else {
            out.println(Fmt.row(in, "texel", "(" + column + ", " + row + ") before it is"
                    + " brought into the " + w + "×" + h + " image (" + where + "): a RepeatTexture wraps it, a ClampTexture clamps it"));
        }
        out.println(Fmt.row(in, "kd", Fmt.vec(kd) + "   (" + texture.getClass().getSimpleName() + ".getTexColor(u, v))"));
    }

    /**
     * What a wrong lookup's color is, in the course's terms (column, row from the file's top): the
     * texel of the mirrored row (rows not flipped) or column, a neighbour (rounded another way), black
     * from an image that has no black there (the stub), or none of these. The checks run in that
     * order, so a color that two of them explain is named by the first.
     */
    static String whichTexel(Image image, int column, int row, Vec3 kd) {
        int w = image.width();
        int h = image.height();
        if (h > 1 && kd.equals(texelFromTop(image, column, h - 1 - row))) {
            return "that is texel (" + column + ", " + (h - 1 - row) + "), the same column in the mirrored row: are the rows"
                    + " flipped? Row 0 is the top of the image file, and v = 1 is the top of the texture.";
        }
        if (w > 1 && kd.equals(texelFromTop(image, w - 1 - column, row))) {
            return "that is texel (" + (w - 1 - column) + ", " + row + "), the same row in the mirrored column: column 0 is the"
                    + " image's left edge, where u = 0.";
        }
        for (int[] d : new int[][] {{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
            int c = column + d[0];
            int r = row + d[1];
            if (c >= 0 && c < w && r >= 0 && r < h && kd.equals(texelFromTop(image, c, r))) {
                return "that is the neighbouring texel (" + c + ", " + r + "): is u·W or (1 − v)·H rounded another way"
                        + " (add ½, then cast, once)?";
            }
        }
        if (kd.equals(Vec3.ZERO)) {
            return "black, which this texel is not: is it still the stub?";
        }
        return "no texel near it has that color.";
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
