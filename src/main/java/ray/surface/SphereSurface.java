package ray.surface;

import ray.math.PositiveNumber;
import ray.math.Vec3;

/**
 * A sphere's data, for the student's {@link Sphere}, which adds the ray test: the points at
 * distance {@code radius} from {@code center}. (What the framework knows of a sphere besides is in
 * {@link SphereFacts}.)
 */
public abstract class SphereSurface extends Surface {
    protected Vec3 center = Vec3.ZERO;
    protected double radius = 1.0;

    public Vec3 getCenter() {
        return center;
    }

    public void setCenter(Vec3 center) {
        this.center = center;
    }

    public double getRadius() {
        return radius;
    }

    /** @throws IllegalArgumentException unless the radius is a positive finite number */
    public void setRadius(double radius) {
        this.radius = PositiveNumber.require("radius", radius);
    }
}
