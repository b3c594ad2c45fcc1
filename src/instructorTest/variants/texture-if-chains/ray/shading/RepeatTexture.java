package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Wraps with while loops, as a first-year student might. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = (int) (u * image.width() + 0.5);
        int row = (int) ((1 - v) * image.height() + 0.5);
        while (column >= image.width()) {
            column -= image.width();
        }
        while (column < 0) {
            column += image.width();
        }
        while (row >= image.height()) {
            row -= image.height();
        }
        while (row < 0) {
            row += image.height();
        }
        return texel(column, row);
    }
}
