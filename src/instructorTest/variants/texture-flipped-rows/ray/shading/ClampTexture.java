package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: flips the row itself, though the image's rows already count from the bottom. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int i = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width() + 0.5)));
        int j = Math.max(0, Math.min(image.height() - 1, (int) (v * image.height() + 0.5)));
        return image.get(i, image.height() - 1 - j);
    }
}
