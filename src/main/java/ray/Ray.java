package ray;

import ray.math.Vec3;

/**
 * A ray segment: the points r(t) = origin + t·direction for start &lt; t &lt; end.
 *
 * <p>The direction is <b>not</b> assumed to be unit length: a camera ray's direction has the
 * length of the vector to its image-plane point, and a transformed ray keeps its t values
 * because its direction is transformed but not renormalized. Code that needs a unit
 * vector normalizes its own copy.
 *
 * <p>{@code start} and {@code end} may be changed by the code that owns the ray (a group
 * shortens its working copy to the closest hit so far); a surface's {@code intersect} only reads them.
 */
public final class Ray {
    public final Vec3 origin;
    public final Vec3 direction;
    public double start;
    public double end;

    /** A ray from {@code origin} that starts at t = 0 and never ends. */
    public Ray(Vec3 origin, Vec3 direction) {
        this(origin, direction, 0, Double.POSITIVE_INFINITY);
    }

    public Ray(Vec3 origin, Vec3 direction, double start, double end) {
        this.origin = origin;
        this.direction = direction;
        this.start = start;
        this.end = end;
    }

    /** The point r(t) = origin + t·direction. */
    public Vec3 pointAt(double t) {
        return origin.plusScaled(t, direction);
    }

    /** A copy of this ray that its owner can shorten without changing this one. */
    public Ray copy() {
        return new Ray(origin, direction, start, end);
    }

    @Override
    public String toString() {
        return "Ray[origin " + origin + ", direction " + direction + ", t in (" + start + ", " + end + ")]";
    }
}
