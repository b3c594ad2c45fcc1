package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds down with Math.floor(v·H + 0.5) and flips to H − j, the nearest texel everywhere but on an edge between rows, where it takes the upper row and the course the lower. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width() + 0.5)));
        int row = Math.max(0, Math.min(image.height() - 1, image.height() - (int) Math.floor(v * image.height() + 0.5)));
        return texel(column, row);
    }
}
