package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Math.round of double products, clamped as longs. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        long column = Math.round(u * image.width());
        long row = Math.round((1 - v) * image.height());
        int i = (int) Math.max(0, Math.min(image.width() - 1, column));
        int r = (int) Math.max(0, Math.min(image.height() - 1, row));
        return texel(i, r);
    }
}
