package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** Wraps u and v into [0, 1) first, then takes the texel with Math.floor. */
public class RepeatTexture extends Texture {
    public RepeatTexture() {
    }

    public RepeatTexture(Image image) {
        super(image);
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        double wrappedU = u - Math.floor(u);
        double wrappedV = v - Math.floor(v);
        int column = (int) Math.floor(wrappedU * image.width() + 0.5);
        int row = (int) Math.floor((1 - wrappedV) * image.height() + 0.5);
        // u just below 1 rounds up to column W, and v = 0 to row H: both are index 0 again.
        return texel(column % image.width(), row % image.height());
    }
}
