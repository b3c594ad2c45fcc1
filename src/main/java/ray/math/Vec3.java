package ray.math;

import java.util.function.DoubleFunction;

/**
 * An immutable triple of doubles: a point, a direction or an RGB color.
 *
 * <p>Every operation returns a new vector. The JIT's escape analysis removes most of these
 * short-lived objects in the hot loop, so the code can read like the math.
 */
public final class Vec3 {
    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    public static final Vec3 ONE = new Vec3(1, 1, 1);

    public final double x;
    public final double y;
    public final double z;

    public Vec3(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    public Vec3 plus(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    public Vec3 minus(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    public Vec3 times(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    /** Component-wise product, e.g. a diffuse color times a light's intensity. */
    public Vec3 times(Vec3 o) {
        return new Vec3(x * o.x, y * o.y, z * o.z);
    }

    /** this + s·o, the point at parameter s along a ray from this with direction o. */
    public Vec3 plusScaled(double s, Vec3 o) {
        return new Vec3(x + s * o.x, y + s * o.y, z + s * o.z);
    }

    public Vec3 negate() {
        return new Vec3(-x, -y, -z);
    }

    public double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    public double lengthSquared() {
        return x * x + y * y + z * z;
    }

    public double length() {
        return Math.sqrt(lengthSquared());
    }

    /** This vector scaled to unit length; a zero vector stays zero rather than becoming NaN. */
    public Vec3 normalized() {
        double len = length();
        if (len > 0 && len < Double.POSITIVE_INFINITY) {
            return new Vec3(x / len, y / len, z / len);
        }
        // |v|² underflowed (coordinates below ~1e-154) or overflowed (above ~1e154): divide by the
        // largest coordinate first, which is exact in direction, then normalize the rescaled vector.
        double m = maxAbs();
        if (m > 0 && m < Double.POSITIVE_INFINITY) {
            Vec3 rescaled = new Vec3(x / m, y / m, z / m);
            double l = rescaled.length();
            return new Vec3(rescaled.x / l, rescaled.y / l, rescaled.z / l);
        }
        return this;
    }

    /** The largest absolute coordinate: the scale that rounding errors of this point grow with. */
    public double maxAbs() {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    public double get(int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof Vec3)) {
            return false;
        }
        Vec3 v = (Vec3) o;
        return Double.compare(x, v.x) == 0 && Double.compare(y, v.y) == 0 && Double.compare(z, v.z) == 0;
    }

    @Override
    public int hashCode() {
        return Double.hashCode(x) * 961 + Double.hashCode(y) * 31 + Double.hashCode(z);
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ", " + z + ")";
    }

    /** "(x, y, z)", each coordinate written by {@code number} (as {@code ray1 trace} rounds them). */
    public String format(DoubleFunction<String> number) {
        return "(" + number.apply(x) + ", " + number.apply(y) + ", " + number.apply(z) + ")";
    }
}
