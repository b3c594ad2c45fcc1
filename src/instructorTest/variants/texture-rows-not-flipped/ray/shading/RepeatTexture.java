package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: takes (int)(v·H + 0.5) as the row from the top, so the image is upside down. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.floorMod((int) (u * image.width() + 0.5), image.width());
        int row = Math.floorMod((int) (v * image.height() + 0.5), image.height());
        return texel(column, row);
    }
}
