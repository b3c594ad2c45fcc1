package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Wraps with while loops, as a first-year student might. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int i = (int) (u * image.width() + 0.5);
        int j = (int) (v * image.height() + 0.5);
        while (i >= image.width()) {
            i -= image.width();
        }
        while (i < 0) {
            i += image.width();
        }
        while (j >= image.height()) {
            j -= image.height();
        }
        while (j < 0) {
            j += image.height();
        }
        return image.get(i, j);
    }
}
