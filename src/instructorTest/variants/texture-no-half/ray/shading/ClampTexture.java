package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds down with (int)(u·W) without + 0.5, so it takes the texel whose corner, not center, is nearest. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width())));
        int row = Math.max(0, Math.min(image.height() - 1, (int) ((1 - v) * image.height())));
        return texel(column, row);
    }
}
