package ray.surface;

import ray.math.Vec3;

/**
 * What a sphere and a cylinder both are: a surface around a {@code center} with a {@code radius},
 * which moves with its center (its data for {@link SphereShape} and {@link CylinderShape}).
 */
public abstract class RoundShape extends Surface {
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

    public void setRadius(double radius) {
        this.radius = positive("radius", radius);
    }

    /** {@code value}, checked to be a positive finite number (the scene file's one-line error otherwise). */
    protected static double positive(String name, double value) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(name + " is " + value + "; expected a positive number");
        }
        return value;
    }

    /** A copy with its center moved into the frame whose origin is {@code origin}. */
    @Override
    public Surface inFrameAt(Vec3 origin) {
        RoundShape moved = (RoundShape) copy();
        moved.center = center.minus(origin);
        return moved;
    }
}
