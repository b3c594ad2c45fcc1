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
        int i = Math.round((float) u * w);
        int j = Math.round((float) v * h);
        return image.get(Math.floorMod(i, w), Math.floorMod(j, h));
    }
}
