package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** A texture whose edge texels extend beyond [0, 1]: coordinates outside are clamped to the image. */
public class ClampTexture extends Texture {

    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        // TODO(Task 5): return the color of the texel that (u, v) picks, clamped to the image.
        //   Return the color of the texel that (u, v) picks, clamped to the image.
        //   Conventions (the reference images depend on them):
        //   - u runs left to right and v bottom to top over the image; texel(column, row) counts rows from
        //     the image's top.
        //   - The texel picked is the nearest: its column is u·W rounded to the nearest whole number (W the
        //     image's width) and its row (1 − v)·H rounded so (H its height), halves rounded up; either way
        //     of rounding a value below zero is accepted.
        //   - A column or row outside the image is clamped to the nearest edge's (u = 1.25 reads the
        //     right-hand column).
        // HINTS steps
        //   1) Find the column and row as in RepeatTexture.
        //   2) Clamp each to the image's range of columns and rows.
        //   3) Return that texel.
        // HINTS formulas
        //   1) With W = image.width() and H = image.height(), the column is i = (int) (u·W + 0.5) and
        //      the row, counted from the image's top, is (int) ((1 − v)·H + 0.5), as in RepeatTexture.
        //      (int) Math.floor(…) is just as right: after the clamping it picks the same texel everywhere.
        //   2) Clamp the column to 0 … W − 1 and the row to 0 … H − 1, so that u = 1.25 reads the
        //      right-hand column and v = 1.25 the top row.
        //   3) Return texel(column, row).
        // END HINTS
        // BEGIN SOLUTION
        int column = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width() + 0.5)));
        int row = Math.max(0, Math.min(image.height() - 1, (int) ((1 - v) * image.height() + 0.5)));
        return texel(column, row);
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
