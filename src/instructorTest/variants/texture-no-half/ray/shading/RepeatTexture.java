package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds down with (int)(u·W) without + 0.5, so it takes the texel whose corner, not center, is nearest. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.floorMod((int) (u * image.width()), image.width());
        int row = Math.floorMod((int) ((1 - v) * image.height()), image.height());
        return texel(column, row);
    }
}
