package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: clamps to W and H, one past the last column and row. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.max(0, Math.min(image.width(), (int) (u * image.width() + 0.5)));
        int row = Math.max(0, Math.min(image.height(), (int) ((1 - v) * image.height() + 0.5)));
        return texel(column, row);
    }
}
