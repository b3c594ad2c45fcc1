package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Reads the image directly: image.get counts rows from the bottom, so the row from the top is turned round. */
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
        int column = Math.floorMod((int) (u * w + 0.5), w);
        int fromTop = Math.floorMod((int) ((1 - v) * h + 0.5), h);
        return image.get(column, h - 1 - fromTop);
    }
}
