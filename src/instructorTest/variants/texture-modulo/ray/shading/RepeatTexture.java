package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Java's % with the sign fixed by hand. */
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
        int i = (int) (u * w + 0.5) % w;
        int j = (int) (v * h + 0.5) % h;
        if (i < 0) {
            i += w;
        }
        if (j < 0) {
            j += h;
        }
        return image.get(i, j);
    }
}
