package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Clamps with if/else chains. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int i = (int) (u * image.width() + 0.5);
        int j = (int) (v * image.height() + 0.5);
        if (i < 0) {
            i = 0;
        } else if (i > image.width() - 1) {
            i = image.width() - 1;
        }
        if (j < 0) {
            j = 0;
        } else if (j > image.height() - 1) {
            j = image.height() - 1;
        }
        return image.get(i, j);
    }
}
