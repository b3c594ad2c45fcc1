package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds v·H + 0.5 to a row from the bottom and flips it to H − 1 − j, one row off at every v (the course flips v before rounding). */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.floorMod((int) (u * image.width() + 0.5), image.width());
        int fromBottom = Math.floorMod((int) (v * image.height() + 0.5), image.height());
        return texel(column, image.height() - 1 - fromBottom);
    }
}
