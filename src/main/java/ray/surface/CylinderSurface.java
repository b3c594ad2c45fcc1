package ray.surface;

import ray.math.PositiveNumber;
import ray.math.Vec3;

/**
 * A capped cylinder's data, for the student's {@link Cylinder} (extra credit), which adds the ray
 * test: the solid whose bottom cap is the disc of {@code radius} about {@code center} in the plane
 * y = center.y, rising along +y by {@code height}. Any other orientation is a {@code <rotate>} away,
 * as for every surface. (What the framework knows of a cylinder besides is in {@link CylinderFacts}.)
 */
public abstract class CylinderSurface extends Surface {
    protected Vec3 center = Vec3.ZERO;
    protected double radius = 1.0;
    protected double height = 1.0;

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

    public double getHeight() {
        return height;
    }

    /** @throws IllegalArgumentException unless the height is a positive finite number */
    public void setHeight(double height) {
        this.height = PositiveNumber.require("height", height);
    }
}
