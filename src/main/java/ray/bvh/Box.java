package ray.bvh;

import ray.math.Vec3;

/**
 * An axis-aligned box, from its smallest corner {@link #min} to its largest {@link #max}: every
 * point p with min.x ≤ p.x ≤ max.x, and the same on y and z. A box may be flat (min = max on an
 * axis, as around a triangle that lies in a plane x = c) but never inside out.
 */
public final class Box {
    public final Vec3 min;
    public final Vec3 max;

    /** @throws IllegalArgumentException when a corner is not finite or min is above max on some axis */
    public Box(Vec3 min, Vec3 max) {
        if (min == null || max == null || !min.isFinite() || !max.isFinite()) {
            throw new IllegalArgumentException("a box's corners must be finite, got " + min + " and " + max);
        }
        if (min.x > max.x || min.y > max.y || min.z > max.z) {
            throw new IllegalArgumentException("a box's min must not be above its max on any axis, got min " + min + ", max " + max);
        }
        this.min = min;
        this.max = max;
    }

    /** The smallest box holding this one and {@code other}. */
    public Box union(Box other) {
        return new Box(new Vec3(Math.min(min.x, other.min.x), Math.min(min.y, other.min.y), Math.min(min.z, other.min.z)),
                new Vec3(Math.max(max.x, other.max.x), Math.max(max.y, other.max.y), Math.max(max.z, other.max.z)));
    }

    /** Whether every point of {@code other} is in this box (faces included). */
    public boolean contains(Box other) {
        return min.x <= other.min.x && min.y <= other.min.y && min.z <= other.min.z
                && other.max.x <= max.x && other.max.y <= max.y && other.max.z <= max.z;
    }

    /** The point halfway between the corners. */
    public Vec3 center() {
        return min.plus(max).times(0.5);
    }

    /** Its extent along {@code axis} (0 for x, 1 for y, 2 for z). */
    public double size(int axis) {
        return max.get(axis) - min.get(axis);
    }

    /** The axis (0, 1 or 2) along which it is longest; the first of equals. */
    public int longestAxis() {
        return size(0) >= size(1) && size(0) >= size(2) ? 0 : size(1) >= size(2) ? 1 : 2;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Box && ((Box) o).min.equals(min) && ((Box) o).max.equals(max);
    }

    @Override
    public int hashCode() {
        return 31 * min.hashCode() + max.hashCode();
    }

    @Override
    public String toString() {
        return "Box[" + min + " to " + max + "]";
    }
}
