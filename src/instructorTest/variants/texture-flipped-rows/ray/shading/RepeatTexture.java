package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: flips the row itself, though the image's rows already count from the bottom. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int i = Math.floorMod((int) (u * image.width() + 0.5), image.width());
        int j = Math.floorMod((int) (v * image.height() + 0.5), image.height());
        return image.get(i, image.height() - 1 - j);
    }
}
