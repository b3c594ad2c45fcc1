package ray.render;

import ray.Ray;
import ray.math.Vec3;
import ray.surface.HitGeometry;

/**
 * How rays that leave a surface avoid hitting it again at their own origin ("shadow acne"): the
 * three rules a renderer can choose from, which the accuracy report compares. Every render uses
 * {@link #SCALED}; the other two exist to show what it fixes.
 */
public enum RayOffsets {
    /** No offset: new rays start at the computed hit point with t &gt; 0. About half re-hit their surface. */
    NONE("none"),
    /**
     * The textbook rule: new rays start at the computed hit point and ignore hits closer than a fixed
     * distance {@link #FIXED_EPSILON} (t_min = ε/|d|). Right for scenes of size ~1 near the origin;
     * too small far from it (the hit point's error grows with its coordinates) and too large for
     * features smaller than ε.
     */
    FIXED("fixed 1e-6"),
    /** The framework's rule ({@link SecondaryRays}): off the re-projected hit along the geometric normal, by a bound scaled to the coordinates. */
    SCALED("scaled"),
    /**
     * The framework's rule sized for intersection tests that compute in float: the same
     * {@link SecondaryRays#OFFSET_ULPS} units, of float's ε = 2⁻²⁴ instead of double's 2⁻⁵³. A float
     * test rounds a new ray's origin to float, which moves it by up to 2⁻²⁴ of its coordinates,
     * so double-sized offsets leave it on either side of the surface.
     */
    SCALED_FOR_FLOAT("scaled for float"),
    /**
     * pbrt-v4's rule: off the re-projected hit by the bound on its own error ({@link ray.surface.HitGeometry#error}),
     * no more: the smallest offset that puts the origin on the right side of the surface, which does
     * not cover the error of a textbook intersection test of the new ray.
     */
    ERROR_BOUND("error bound");

    // The rules are switches rather than constant-specific bodies: a constant with a body compiles
    // to a sealed enum with subclasses, a class file that Debian's Gradle 4.4 reports as malformed
    // on every first compile.

    /** Float's unit roundoff, 2⁻²⁴. */
    static final double FLOAT_EPSILON = 0x1p-24;

    /** The fixed rule's distance, in scene units: the 1e-6 of the numerics issue's tolerance survey. */
    public static final double FIXED_EPSILON = 1e-6;

    public final String label;

    RayOffsets(String label) {
        this.label = label;
    }

    /** The segment from the hit toward the light that a shadow test traces. */
    public Ray shadowRay(HitGeometry g, Vec3 lightPosition) {
        switch (this) {
            case NONE:
                return new Ray(g.location, lightPosition.minus(g.location), 0, SecondaryRays.SHADOW_END);
            case FIXED:
                Vec3 d = lightPosition.minus(g.location);
                return new Ray(g.location, d, FIXED_EPSILON / d.length(), SecondaryRays.SHADOW_END);
            case SCALED:
                return SecondaryRays.shadowRay(g, lightPosition);
            case ERROR_BOUND:
                return SecondaryRays.errorBoundShadowRay(g, lightPosition);
            default:
                return SecondaryRays.shadowRay(g, lightPosition, FLOAT_EPSILON);
        }
    }

    /** The ray from the hit in {@code direction} that a reflection traces. */
    public Ray reflectionRay(HitGeometry g, Vec3 direction) {
        switch (this) {
            case NONE:
                return new Ray(g.location, direction);
            case FIXED:
                return new Ray(g.location, direction, FIXED_EPSILON / direction.length(), Double.POSITIVE_INFINITY);
            case SCALED:
                return SecondaryRays.reflectionRay(g, direction);
            case ERROR_BOUND:
                return SecondaryRays.errorBoundReflectionRay(g, direction);
            default:
                return SecondaryRays.reflectionRay(g, direction, FLOAT_EPSILON);
        }
    }
}
