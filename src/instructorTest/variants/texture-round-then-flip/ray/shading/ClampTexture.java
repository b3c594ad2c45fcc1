package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds v·H + 0.5 first and flips to H − j, which agrees with (int)((1 − v)·H + 0.5) except exactly on the edges between texel rows. */
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
