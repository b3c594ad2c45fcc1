package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Clamps u and v to [0, 1] first, then takes the texel with Math.floor. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        double clampedU = Math.max(0, Math.min(1, u));
        double clampedV = Math.max(0, Math.min(1, v));
        int column = (int) Math.floor(clampedU * image.width() + 0.5);
        int row = (int) Math.floor((1 - clampedV) * image.height() + 0.5);
        return texel(Math.min(column, image.width() - 1), Math.min(row, image.height() - 1));
    }
}
