package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** A correct repeat (this variant's mistake is in its clamp). */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.floorMod((int) (u * image.width() + 0.5), image.width());
        int row = Math.floorMod((int) ((1 - v) * image.height() + 0.5), image.height());
        return texel(column, row);
    }
}
