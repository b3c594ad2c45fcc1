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
        // TODO(Task 5): return the color of the texel nearest to (u, v), repeating the image.
        //   1) With W = image.width() and H = image.height(), the nearest texel is column
        //      i = (int) (u·W + 0.5) and row j = (int) (v·H + 0.5). Use the cast as written: the
        //      reference images round this way ((int) drops the fraction, toward zero).
        //   2) Wrap i into 0 … W − 1 and j into 0 … H − 1, so that u = 1.25 reads like u = 0.25. Careful:
        //      Java's % keeps the sign of a negative i (−1 % W is −1); Math.floorMod(i, W) does not.
        //   3) Return image.get(i, j) (j counts rows from the image's bottom, as v does).
        // BEGIN SOLUTION
        int width = image.width();
        int height = image.height();
        int i = Math.floorMod((int) (u * width + 0.5), width);
        int j = Math.floorMod((int) (v * height + 0.5), height);
        return image.get(i, j);
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
