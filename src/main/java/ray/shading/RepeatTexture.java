package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** A texture that tiles: beyond [0, 1] its coordinates wrap around, so the image repeats. */
public class RepeatTexture extends Texture {

    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        // TODO(Task 5): return the color of the texel that (u, v) picks, repeating the image.
        //   Return the color of the texel that (u, v) picks, repeating the image in both directions.
        //   Conventions (the reference images depend on them):
        //   - u runs left to right and v bottom to top over the image; texel(column, row) counts rows from
        //     the image's top.
        //   - The texel picked is the nearest: its column is u·W rounded to the nearest whole number (W the
        //     image's width) and its row (1 − v)·H rounded so (H its height), halves rounded up; either way
        //     of rounding a value below zero is accepted.
        //   - A column or row outside the image wraps around (u = 1.25 reads as u = 0.25).
        // HINTS steps
        //   1) Scale u by the width and 1 − v by the height (rows count down from the top), and round each
        //      to the nearest whole number.
        //   2) Wrap each into the image (careful: Java's % keeps the sign of a negative number).
        //   3) Return that texel.
        // HINTS formulas
        //   1) With W = image.width() and H = image.height(), the column is i = (int) (u·W + 0.5) and
        //      the row, counted from the image's top, is (int) ((1 − v)·H + 0.5). v counts up from the
        //      bottom but rows count down from the top, so turn v into 1 − v first, then scale and round
        //      (flipping after the rounding, H − 1 − (int) (v·H + 0.5), is one row off everywhere). The
        //      cast (int) drops the fraction, as the reference renderer does; (int) Math.floor(…) is just
        //      as right: the same texel wherever the value is ≥ 0, one texel over where it is negative
        //      (u below −½ texel, v above 1 + ½ texel), and the tests accept either texel there.
        //   2) Wrap the column into 0 … W − 1 and the row into 0 … H − 1, so that u = 1.25 reads like
        //      u = 0.25. Careful: Java's % keeps the sign of a negative number (−1 % W is −1);
        //      Math.floorMod(i, W) does not.
        //   3) Return texel(column, row).
        // END HINTS
        // BEGIN SOLUTION
        int width = image.width();
        int height = image.height();
        int column = Math.floorMod((int) (u * width + 0.5), width);
        int row = Math.floorMod((int) ((1 - v) * height + 0.5), height);
        return texel(column, row);
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
