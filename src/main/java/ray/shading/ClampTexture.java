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
        // TODO(Task 5): return the color of the texel nearest to (u, v), clamped to the image.
        //   1) With W = image.width() and H = image.height(), the nearest texel is column
        //      i = (int) (u·W + 0.5) and row j = (int) (v·H + 0.5), as in RepeatTexture.
        //   2) Clamp i to 0 … W − 1 and j to 0 … H − 1, so that u = 1.25 reads the right-hand column.
        //   3) Return image.get(i, j) (j counts rows from the image's bottom, as v does).
        // BEGIN SOLUTION
        int i = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width() + 0.5)));
        int j = Math.max(0, Math.min(image.height() - 1, (int) (v * image.height() + 0.5)));
        return image.get(i, j);
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
