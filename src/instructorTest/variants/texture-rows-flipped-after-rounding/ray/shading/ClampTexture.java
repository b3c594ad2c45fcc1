package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds v·H + 0.5 to a row from the bottom and flips it to H − 1 − j, one row off at every v (the course flips v before rounding). */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width() + 0.5)));
        int fromBottom = Math.max(0, Math.min(image.height() - 1, (int) (v * image.height() + 0.5)));
        return texel(column, image.height() - 1 - fromBottom);
    }
}
