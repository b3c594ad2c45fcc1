package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Math.min and Math.max in the other order. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int w = image.width();
        int h = image.height();
        int column = (int) (u * w + 0.5);
        int row = (int) ((1 - v) * h + 0.5);
        return texel(Math.min(Math.max(column, 0), w - 1), Math.min(Math.max(row, 0), h - 1));
    }
}
