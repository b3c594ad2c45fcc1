package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds v·H + 0.5 first and flips to H − j, so for v below 0 the cast, rounding toward zero, lands a row off, and on an edge between rows it takes the upper row where the course takes the lower. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width() + 0.5)));
        int row = Math.max(0, Math.min(image.height() - 1, image.height() - (int) (v * image.height() + 0.5)));
        return texel(column, row);
    }
}
