package ray.render;

import ray.Ray;
import ray.math.Vec3;
import ray.surface.HitGeometry;

/**
 * Where rays that leave a surface start and end. A computed hit point is off the true surface by
 * rounding error, so a new ray starting exactly there hits the same surface again about half the
 * time ("shadow acne"). It starts instead a little off the surface, on the side it leaves to, and
 * a shadow ray stops just short of its light.
 *
 * <p>How far off, and along what, follows pbrt's {@code OffsetRayOrigin} (Pharr, Jakob and
 * Humphreys, <i>Physically Based Rendering</i>, 4th ed., §6.8.6): along the <b>geometric</b>
 * normal, by a bound on the error of the hit point. Here that bound is {@link #OFFSET_ULPS}·ε·scale
 * (ε = 2⁻⁵³), where scale ({@link HitGeometry#scale}) is the magnitude of the numbers the point and
 * the surface are computed from, through every transform: it is relative, so a scene moved or scaled
 * by any power of ten gets the same offsets in proportion (a fixed 1e-3 or 1e-6 does not), and it
 * is not larger than it must be, so it stays far below the features of a small object far from the
 * origin. The point it starts from is the hit re-projected onto the primitive ({@link HitGeometry#point}),
 * so the error of a hit found from far away does not count.
 *
 * <p>Measured by {@code ray.numerics.ReintersectionSweep} (instructor tests; docs/numerics.md has
 * the tables): from hits on spheres, triangles, closed meshes and transformed surfaces of sizes and
 * positions 10^−4…10^6, about 10^6 rays per case, none re-hits its surface with this offset, with
 * the solution's intersection code and with textbook code alike; 23–50% do with no offset
 * (t_min = 0), up to 14% with a fixed t_min of 1e-6, and 42–48% with that t_min 10^12 from the
 * origin. The rule used before, 1e-9·(1 + max|p_i|) along the shading normal, re-hit 23% of the rays
 * from smooth-shaded triangles (the shading normal put them on the wrong side), 0.46% from
 * triangles seen from far away (the hit's error grows with the ray's length) and 0.1–0.2% from
 * small bodies far from the origin hit from inside (the offset was larger than the body).
 */
public final class SecondaryRays {
    /**
     * The offset in units of ε·scale. The errors of a re-projected point and of a new ray's own test
     * are a few ε·scale: in the sweep, 2 still re-hits (up to 0.4% of the rays) and 4 never does with
     * the solution's code. Textbook code needs more: on a closed mesh, a Cramer's-rule test of a
     * neighbor that a ray grazes along their shared edge re-hits 28, 10, 4 and 2 rays per million at
     * 4, 16, 64 and 256, and none at 1024. And 1024·ε ≈ 1.1e-13 of the coordinates stays far below
     * any feature: only at 2^24 do offsets jump over bodies of size 10^−4 at 10^6 from the origin.
     */
    public static final double OFFSET_ULPS = 1024;
    /** A shadow ray covers the segment to the light up to this fraction, so the light itself never blocks. */
    public static final double SHADOW_END = 1 - 1e-9;

    private static final double EPSILON = 0x1p-53;

    private SecondaryRays() {
    }

    /** How far off the surface rays from a hit with geometry {@code g} start. */
    public static double offset(HitGeometry g) {
        return OFFSET_ULPS * EPSILON * g.scale;
    }

    /** The hit point pushed off the surface, along its geometric normal, toward the side that {@code direction} points to. */
    public static Vec3 offsetOrigin(HitGeometry g, Vec3 direction) {
        return offsetOrigin(g, direction, EPSILON);
    }

    /**
     * The same with the unit roundoff of another arithmetic: {@code 0x1p-24} for intersection
     * tests that compute in float, whose hit points and tests err by float's ε, not double's.
     */
    static Vec3 offsetOrigin(HitGeometry g, Vec3 direction, double unitRoundoff) {
        double offset = OFFSET_ULPS * unitRoundoff * g.scale;
        return g.point.plusScaled(g.normal.dot(direction) >= 0 ? offset : -offset, g.normal);
    }

    /**
     * The hit point pushed off the surface by its own error bound (pbrt-v4's {@code OffsetRayOrigin},
     * §6.8.6): d = |n|·error along the geometric normal, toward {@code direction}'s side, and each
     * coordinate then rounded one double further away, so that the sum's own rounding cannot bring
     * it back. As small as the point's error allows, it does not cover the error of the new ray's
     * own test, which the scaled rule's 1024 ulps do for textbook code.
     */
    static Vec3 errorBoundOrigin(HitGeometry g, Vec3 direction) {
        return errorBoundOrigin(g, direction, 1);
    }

    /** The same, {@code multiple} times as far (for measuring the margin a textbook test needs). */
    public static Vec3 errorBoundOrigin(HitGeometry g, Vec3 direction, double multiple) {
        Vec3 n = g.normal;
        double d = multiple * (Math.abs(n.x) * g.error.x + Math.abs(n.y) * g.error.y + Math.abs(n.z) * g.error.z);
        if (n.dot(direction) < 0) {
            d = -d;
        }
        Vec3 o = g.point.plusScaled(d, n);
        return new Vec3(awayFrom(o.x, d * n.x), awayFrom(o.y, d * n.y), awayFrom(o.z, d * n.z));
    }

    private static double awayFrom(double x, double offset) {
        return offset > 0 ? Math.nextUp(x) : offset < 0 ? Math.nextDown(x) : x;
    }

    /** The shadow ray of the error-bound rule ({@link #errorBoundOrigin}). */
    static Ray errorBoundShadowRay(HitGeometry g, Vec3 lightPosition) {
        Vec3 origin = errorBoundOrigin(g, lightPosition.minus(g.point));
        return new Ray(origin, lightPosition.minus(origin), 0, SHADOW_END);
    }

    /** The reflection ray of the error-bound rule. */
    static Ray errorBoundReflectionRay(HitGeometry g, Vec3 direction) {
        return new Ray(errorBoundOrigin(g, direction), direction);
    }

    /** The segment from just off the hit to just short of the light: r(t) for 0 < t < SHADOW_END. */
    public static Ray shadowRay(HitGeometry g, Vec3 lightPosition) {
        return shadowRay(g, lightPosition, EPSILON);
    }

    static Ray shadowRay(HitGeometry g, Vec3 lightPosition, double unitRoundoff) {
        Vec3 origin = offsetOrigin(g, lightPosition.minus(g.point), unitRoundoff);
        return new Ray(origin, lightPosition.minus(origin), 0, SHADOW_END);
    }

    public static Ray reflectionRay(HitGeometry g, Vec3 direction) {
        return reflectionRay(g, direction, EPSILON);
    }

    static Ray reflectionRay(HitGeometry g, Vec3 direction, double unitRoundoff) {
        return new Ray(offsetOrigin(g, direction, unitRoundoff), direction);
    }
}
