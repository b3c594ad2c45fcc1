package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Clamps with Math.min and Math.max on the scaled coordinate first. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int w = image.width();
        int h = image.height();
        int i = (int) (u * w + 0.5);
        int j = (int) (v * h + 0.5);
        return image.get(Math.min(Math.max(i, 0), w - 1), Math.min(Math.max(j, 0), h - 1));
    }
}
