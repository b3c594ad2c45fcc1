package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: (int)(u·W) without + 0.5. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int i = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width())));
        int j = Math.max(0, Math.min(image.height() - 1, (int) (v * image.height())));
        return image.get(i, j);
    }
}
