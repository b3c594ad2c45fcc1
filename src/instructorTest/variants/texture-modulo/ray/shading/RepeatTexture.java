package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Java's % with the sign fixed by hand. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int w = image.width();
        int h = image.height();
        int column = (int) (u * w + 0.5) % w;
        int row = (int) ((1 - v) * h + 0.5) % h;
        if (column < 0) {
            column += w;
        }
        if (row < 0) {
            row += h;
        }
        return texel(column, row);
    }
}
