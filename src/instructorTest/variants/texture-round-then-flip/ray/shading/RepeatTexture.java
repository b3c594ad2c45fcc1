package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds v·H + 0.5 first and flips to H − j, so for v below 0 the cast, rounding toward zero, lands a row off, and on an edge between rows it takes the upper row where the course takes the lower. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.floorMod((int) (u * image.width() + 0.5), image.width());
        int row = Math.floorMod(image.height() - (int) (v * image.height() + 0.5), image.height());
        return texel(column, row);
    }
}
