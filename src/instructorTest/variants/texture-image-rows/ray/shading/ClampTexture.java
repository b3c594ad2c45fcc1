package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Reads the image directly, flipping the row from the top into image.get's row from the bottom. */
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
        int column = Math.max(0, Math.min(w - 1, (int) (u * w + 0.5)));
        int fromTop = Math.max(0, Math.min(h - 1, (int) ((1 - v) * h + 0.5)));
        return image.get(column, h - 1 - fromTop);
    }
}
