package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: takes (int)(v·H + 0.5) as the row from the top, so the image is upside down. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.max(0, Math.min(image.width() - 1, (int) (u * image.width() + 0.5)));
        int row = Math.max(0, Math.min(image.height() - 1, (int) (v * image.height() + 0.5)));
        return texel(column, row);
    }
}
