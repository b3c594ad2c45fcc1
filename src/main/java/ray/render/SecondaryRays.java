package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Where rays that leave a surface start and end. A computed hit point is off the true surface by
 * rounding error that grows with its coordinates, so a new ray starting exactly there may hit the
 * same surface again ("shadow acne"). It starts instead a little off the surface, on the side it
 * leaves to, by an amount that scales with the hit point's magnitude (the form Mitsuba uses,
 * (1 + max|p_i|)·ε), and a shadow ray stops just short of its light.
 */
public final class SecondaryRays {
    /** ε of the offset: far above double rounding (~1e-16 relative), far below any scene's features. */
    public static final double RELATIVE_OFFSET = 1e-9;
    /** A shadow ray covers the segment to the light up to this fraction, so the light itself never blocks. */
    public static final double SHADOW_END = 1 - 1e-9;

    private SecondaryRays() {
    }

    /** The hit point pushed off the surface toward the side that {@code direction} points to. */
    public static Vec3 offsetOrigin(IntersectionRecord hit, Vec3 direction) {
        double offset = RELATIVE_OFFSET * (1 + hit.location.maxAbs());
        double side = hit.normal.dot(direction) >= 0 ? offset : -offset;
        return hit.location.plusScaled(side, hit.normal);
    }

    /** The segment from just off the hit to just short of the light: r(t) for 0 < t < SHADOW_END. */
    public static Ray shadowRay(IntersectionRecord hit, Vec3 lightPosition) {
        Vec3 origin = offsetOrigin(hit, lightPosition.minus(hit.location));
        return new Ray(origin, lightPosition.minus(origin), 0, SHADOW_END);
    }

    public static Ray reflectionRay(IntersectionRecord hit, Vec3 direction) {
        return new Ray(offsetOrigin(hit, direction), direction);
    }
}
