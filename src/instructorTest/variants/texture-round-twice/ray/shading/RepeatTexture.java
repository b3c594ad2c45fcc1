package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Known wrong: rounds twice, Math.round(u·W + 0.5) = floor(u·W) + 1, so wherever the fraction of u·W (or (1 − v)·H) is below ½ it takes the next texel, one to the right (or one lower). */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        int column = Math.floorMod((int) Math.round(u * image.width() + 0.5), image.width());
        int row = Math.floorMod((int) Math.round((1 - v) * image.height() + 0.5), image.height());
        return texel(column, row);
    }
}
