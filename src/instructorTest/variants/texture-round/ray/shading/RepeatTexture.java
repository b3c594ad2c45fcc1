package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Math.round of float products (rounds half up, like floor(x + 0.5)). */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int w = image.width();
        int h = image.height();
        int column = Math.round((float) u * w);
        int row = Math.round((float) (1 - v) * h);
        return texel(Math.floorMod(column, w), Math.floorMod(row, h));
    }
}
