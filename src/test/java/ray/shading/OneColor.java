package ray.shading;

import ray.image.Image;
import ray.math.Vec3;

/** A texture of one color everywhere, for tests where the lookup itself is not the point. */
final class OneColor extends Texture {
    private final Vec3 color;

    OneColor(Vec3 color) {
        super(new Image(1, 1));
        this.color = color;
    }

    @Override
    public Vec3 getTexColor(double u, double v) {
        return color;
    }
}
