package ray.surface;

import ray.IntersectionRecord;
import ray.math.Vec3;

/**
 * A hit as the renderer needs it to start new rays there ({@code ray.render.SecondaryRays}),
 * made by the framework after the closest hit is found, from what a surface's {@code intersect}
 * reported, by the hit primitive's own {@link Surface#hitGeometry} (never by students' code):
 * <ul>
 * <li>{@link #location}: the hit as reported (the textbook offsets start there);</li>
 * <li>{@link #point}: the hit re-projected onto the primitive's own surface (a sphere's
 *     center plus radius times the unit direction to the hit, or the hit projected onto a
 *     triangle's plane), so that its distance from the surface is rounding of the surface's own
 *     numbers, however far the ray that found it came (Ray Tracing Gems ch. 6 and 7 re-project
 *     for this reason);</li>
 * <li>{@link #normal}: the unit geometric normal, a triangle's face normal even when its shading
 *     normal is interpolated from vertex normals (pbrt offsets along the geometric normal too: a
 *     tilted shading normal can point a new ray back into its own triangle);</li>
 * <li>{@link #scale}: the largest magnitude of the coordinates that point was computed from (the
 *     hit, the sphere's center plus its radius, the triangle's vertices), through every transform
 *     that placed the primitive. The point's rounding error, and the rounding with which a new
 *     ray's test sees this surface, are a few ε·scale (ε = 2⁻⁵³), even where the point itself is
 *     small: a hit near the origin on a ground sphere of radius 10⁶ is computed from numbers near 10⁶.</li>
 * </ul>
 * Made in the primitive's own coordinates and taken out through the transforms that place the
 * primitive by {@link Placements}.
 */
public final class HitGeometry {
    /** The thinness factor's cap: triangles up to this thin (angles down to ~1e-6 rad) are measured acne-free. */
    public static final double MAX_THINNESS = 1e6;

    public final Vec3 location;
    public final Vec3 point;
    public final Vec3 normal;
    public final double scale;
    /**
     * A bound, per coordinate, on how far {@link #point} may be from the exact point of the surface
     * it stands for (the surface of the primitive's own numbers): pbrt-v4's {@code pError}, the sum
     * of the γ(n)·|x| terms of the operations that computed it (γ(n) = nε/(1 − nε), ε = 2⁻⁵³),
     * through every transform. The error-bound offset ({@code RayOffsets.ERROR_BOUND}) starts new
     * rays |n|·error along the normal.
     */
    public final Vec3 error;

    public HitGeometry(Vec3 location, Vec3 point, Vec3 normal, double scale, Vec3 error) {
        this.location = location;
        this.point = point;
        this.normal = normal;
        this.scale = scale;
        this.error = error;
    }

    /** The geometry of a hit on a surface that knows nothing more of its shape: the reported point and normal. */
    public static HitGeometry atReportedPoint(IntersectionRecord hit) {
        double scale = hit.location.maxAbs();
        // Nothing bounds a reported point's error but the test that found it; take that of the scale rule.
        double guess = 1024 * 0x1p-53 * scale;
        return new HitGeometry(hit.location, hit.location, hit.normal, scale, new Vec3(guess, guess, guess));
    }

    /** γ(n) = nε/(1 − nε), ε = 2⁻⁵³: the bound on the relative error of n rounded operations (Higham, §3.1). */
    public static double gamma(int n) {
        double ne = n * 0x1p-53;
        return ne / (1 - ne);
    }

    @Override
    public String toString() {
        return "HitGeometry[point " + point + ", normal " + normal + ", scale " + scale + ", error " + error + "]";
    }
}
