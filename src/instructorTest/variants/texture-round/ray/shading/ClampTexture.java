package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Math.round of the products, clamped. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        long i = Math.round(u * image.width());
        long j = Math.round(v * image.height());
        int column = (int) Math.max(0, Math.min(image.width() - 1, i));
        int row = (int) Math.max(0, Math.min(image.height() - 1, j));
        return image.get(column, row);
    }
}
