package ray.surface;

import ray.IntersectionRecord;
import ray.math.Affine;
import ray.math.Vec3;

/**
 * A hit as the renderer needs it to start new rays there ({@code ray.render.SecondaryRays}),
 * made by the framework from what a surface's {@code intersect} reported, never by students' code:
 * <ul>
 * <li>{@link #point}: the hit point re-projected onto the primitive's own surface (a sphere's
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
 * Made in the primitive's own coordinates and carried out of each transformed group by
 * {@link Transformed} ({@link #placedBy}); see {@link IntersectionRecord#geometry()}.
 */
public final class HitGeometry {
    /** The thinness factor's cap: triangles up to this thin (angles down to ~1e-6 rad) are measured acne-free. */
    static final double MAX_THINNESS = 1e6;

    public final Vec3 point;
    public final Vec3 normal;
    public final double scale;

    public HitGeometry(Vec3 point, Vec3 normal, double scale) {
        this.point = point;
        this.normal = normal;
        this.scale = scale;
    }

    /** The geometry of {@code hit} in the coordinates its location and surface are given in. */
    public static HitGeometry of(IntersectionRecord hit) {
        Vec3 p = hit.location;
        if (hit.surface instanceof Sphere) {
            Sphere sphere = (Sphere) hit.surface;
            Vec3 center = sphere.getCenter();
            double radius = sphere.getRadius();
            // A sphere's reported normal is its geometric normal, and shaders aim new rays by it, so
            // new rays take their side from it too. It may be more accurate than the direction from
            // the center to the rounded hit point (for a small sphere far from the origin, that
            // difference loses ~1e-7 of its direction), so it is kept unless it is not a direction
            // along the radius at all.
            Vec3 reported = hit.normal == null ? Vec3.ZERO : hit.normal.normalized();
            Vec3 outward = p.minus(center).normalized();
            if (!(outward.lengthSquared() > 0)) {
                // A hit reported at the center itself has no direction from it; the reported normal has to do.
                outward = reported;
            }
            Vec3 normal = Math.abs(reported.dot(outward)) > 0.5 ? reported : outward;
            return new HitGeometry(center.plusScaled(radius, outward), normal, center.maxAbs() + radius);
        }
        if (hit.surface instanceof Triangle) {
            Triangle triangle = (Triangle) hit.surface;
            Vec3 n = triangle.getFaceNormal();
            Vec3 v0 = triangle.getV0();
            Vec3 e1 = triangle.getV1().minus(v0);
            Vec3 e2 = triangle.getV2().minus(v0);
            double coordinates = Math.max(Math.max(v0.maxAbs(), triangle.getV1().maxAbs()),
                    Math.max(triangle.getV2().maxAbs(), p.maxAbs()));
            // A thin triangle's normal and a new ray's test of it (edge functions or Cramer's rule,
            // products of edges that nearly cancel) lose precision in proportion to
            // longest edge² / |e1 × e2|, about 1/sin of its smallest angle (1.15 when equilateral).
            double longest = Math.max(Math.max(e1.lengthSquared(), e2.lengthSquared()), e2.minus(e1).lengthSquared());
            double thinness = longest / e1.cross(e2).length();
            // Capped (and NaN, for a triangle of no area, replaced) so that even a nearly degenerate
            // triangle's rays start within 1e6·(a few ε) of its coordinates' scale.
            thinness = thinness <= MAX_THINNESS ? thinness : MAX_THINNESS;
            // p − ((p − v0)·n) n: the hit on the triangle's plane, wherever the ray that found it came from.
            return new HitGeometry(p.plusScaled(-p.minus(v0).dot(n), n), n, coordinates * thinness);
        }
        return new HitGeometry(p, hit.normal, p.maxAbs());
    }

    /** This geometry taken out of a transformed group to its parent's coordinates by {@code toWorld} (with its inverse). */
    public HitGeometry placedBy(Affine toWorld, Affine toLocal) {
        return new HitGeometry(toWorld.applyToPoint(point), toLocal.applyTransposeToVector(normal).normalized(),
                toWorld.pointScale(scale));
    }

    @Override
    public String toString() {
        return "HitGeometry[point " + point + ", normal " + normal + ", scale " + scale + "]";
    }
}
