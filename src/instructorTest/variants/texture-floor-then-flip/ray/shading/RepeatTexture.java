package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds down with Math.floor(v·H + 0.5) and flips to H − j, the nearest texel everywhere but on an edge between rows, where it takes the upper row and the course the lower. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.floorMod((int) (u * image.width() + 0.5), image.width());
        int row = Math.floorMod(image.height() - (int) Math.floor(v * image.height() + 0.5), image.height());
        return texel(column, row);
    }
}
