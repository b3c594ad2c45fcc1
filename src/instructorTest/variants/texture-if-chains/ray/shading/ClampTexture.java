package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Clamps with if chains. */
public class ClampTexture extends Texture {
    public ClampTexture() {
    }

    public ClampTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = (int) (u * image.width() + 0.5);
        int row = (int) ((1 - v) * image.height() + 0.5);
        if (column < 0) {
            column = 0;
        } else if (column > image.width() - 1) {
            column = image.width() - 1;
        }
        if (row < 0) {
            row = 0;
        } else if (row > image.height() - 1) {
            row = image.height() - 1;
        }
        return texel(column, row);
    }
}
