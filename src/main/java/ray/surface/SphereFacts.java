package ray.surface;

import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;

/** What the framework knows of a sphere ({@link SphereSurface}) besides its ray test. */
final class SphereFacts implements ShapeFacts {
    static final SphereFacts FACTS = new SphereFacts();

    private SphereFacts() {
    }

    /**
     * The hit re-projected to center + radius·(unit direction to the hit), and the coordinates'
     * scale max|center| + radius. The reported normal is kept as the geometric normal, since shaders
     * aim new rays by it: it may be more accurate than the direction from the center to the rounded
     * hit (for a small sphere far from the origin, that direction loses ~1e-7), so only a normal that
     * is not along the radius at all is replaced.
     */
    @Override
    public HitGeometry hitGeometry(Surface s, IntersectionRecord hit) {
        SphereSurface sphere = (SphereSurface) s;
        Vec3 center = sphere.center;
        double radius = sphere.radius;
        Vec3 p = hit.location;
        Vec3 reported = hit.normal == null ? Vec3.ZERO : hit.normal.normalized();
        Vec3 outward = p.minus(center).normalized();
        if (!(outward.lengthSquared() > 0)) {
            // A hit reported at the center itself has no direction from it; the reported normal has to do.
            outward = reported;
        }
        Vec3 normal = Math.abs(reported.dot(outward)) > 0.5 ? reported : outward;
        Vec3 point = center.plusScaled(radius, outward);
        // |outward| = 1 within γ(5) (a difference, a dot product, a square root and a division), which
        // moves the point radially by up to γ(5)·radius·|outward_i| per coordinate; adding the center
        // rounds each coordinate once more. (The direction's own error only slides the point along the sphere.)
        double radial = HitGeometry.gamma(6) * radius;
        double rounding = HitGeometry.gamma(1);
        Vec3 error = new Vec3(radial * Math.abs(outward.x) + rounding * Math.abs(point.x),
                radial * Math.abs(outward.y) + rounding * Math.abs(point.y),
                radial * Math.abs(outward.z) + rounding * Math.abs(point.z));
        return new HitGeometry(p, point, normal, center.maxAbs() + radius, error);
    }

    /** The cube about the center with half-side |radius|. */
    @Override
    public Bounds bounds(Surface s) {
        SphereSurface sphere = (SphereSurface) s;
        return Bounds.around(sphere.center, sphere.radius);
    }

    /** A copy with its center moved into the frame whose origin is {@code origin}. */
    @Override
    public Surface inFrameAt(Surface s, Vec3 origin) {
        SphereSurface moved = (SphereSurface) s.shallowCopy();
        moved.center = ((SphereSurface) s).center.minus(origin);
        return moved;
    }

    @Override
    public String name(Surface s) {
        SphereSurface sphere = (SphereSurface) s;
        return "Sphere[center " + sphere.center + ", radius " + sphere.radius + "]";
    }

    @Override
    public SurfaceKind kind() {
        return SurfaceKind.SPHERE;
    }

    @Override
    public String describe(Surface s, DoubleFunction<String> number) {
        SphereSurface sphere = (SphereSurface) s;
        return "Sphere center " + ShapeFacts.vec(sphere.center, number) + ", radius " + number.apply(sphere.radius);
    }

    /**
     * The far root: the ray starts outside the sphere, yet the normal faces along the ray (n·d > 0), as
     * it does where the ray leaves the sphere. Only for a hit that lies on the sphere as given (not
     * moved by a transform), so that the eye's place can be compared with the center.
     */
    @Override
    public String doubtAbout(Surface s, IntersectionRecord hit, Ray ray) {
        SphereSurface sphere = (SphereSurface) s;
        Vec3 center = sphere.center;
        double radius = sphere.radius;
        boolean onTheSphere = Math.abs(hit.location.minus(center).length() - radius) <= 1e-6 * (radius + center.length());
        boolean outside = ray.origin.minus(center).length() > radius;
        if (!onTheSphere || !outside || !(hit.normal.dot(ray.direction) > 0)) {
            return null;
        }
        return "the ray starts outside the sphere, yet this normal faces away from the eye (n·d > 0), as it does where"
                + " the ray leaves the sphere: is this the far root? The hit is the smaller root inside (start, end)";
    }

    /** A sphere that is only moved stays a sphere; one turned or scaled is drawn as its bounding box. */
    @Override
    public void sketch(Surface s, Sketch sketch, Affine toWorld) {
        SphereSurface sphere = (SphereSurface) s;
        if (toWorld.isTranslation()) {
            sketch.sphere(toWorld.applyToPoint(sphere.center), sphere.radius);
        } else {
            ShapeFacts.super.sketch(s, sketch, toWorld);
        }
    }
}
