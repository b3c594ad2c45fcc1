package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: clamps to W and H instead of W − 1 and H − 1, one past the last texel. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int i = Math.max(0, Math.min(image.width(), (int) (u * image.width() + 0.5)));
        int j = Math.max(0, Math.min(image.height(), (int) (v * image.height() + 0.5)));
        return image.get(i, j);
    }
}
