package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: (int)(u·W) without + 0.5, the texel whose corner, not center, is nearest. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int i = Math.floorMod((int) (u * image.width()), image.width());
        int j = Math.floorMod((int) (v * image.height()), image.height());
        return image.get(i, j);
    }
}
