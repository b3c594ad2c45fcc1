package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Names the likely cause of a wrong intersection only when the numbers identify it: the returned t
 * is the sphere's other root, or the expected t times |d| (the direction was normalized but t was
 * not scaled back), or a returned hit lies outside the ray's segment or outside the triangle, or a
 * "miss" left a hit in the record (a group returning whether its last child was hit). A
 * hint that merely guesses would send a student after a bug they do not have, so each returns
 * null unless the returned numbers match the cause. These run only after a check has failed; they
 * never decide a test.
 */
public final class HitHints {
    /** How close (relative) a returned t must be to a candidate cause's t to name it. */
    private static final double SAME = 1e-9;

    private HitHints() {
    }

    /** Why a hit came back at {@code actual} instead of {@code expected}, or null when the numbers do not say. */
    public static String forWrongT(Surface surface, Ray ray, double expected, double actual) {
        // The sphere's other root is the more telling name, even outside the segment.
        if (surface instanceof SphereSurface) {
            String root = otherRoot((SphereSurface) surface, ray, expected, actual);
            if (root != null) {
                return root;
            }
        }
        if (!(ray.start < actual && actual < ray.end)) {
            return outsideTheSegment(surface, ray, actual);
        }
        double length = ray.direction.length();
        if (!same(length, 1) && same(actual, expected * length)) {
            return "that is the expected t times |d| = " + HitMessages.number(length)
                    + ", the distance along the normalized direction: for this ray, whose direction is not unit length,"
                    + " t is that distance divided by |d|";
        }
        return null;
    }

    /** Why a hit that should have been a miss is not one, or null when the numbers do not say. */
    public static String forUnexpectedHit(Surface surface, Ray ray, IntersectionRecord out) {
        if (!(ray.start < out.t && out.t < ray.end)) {
            return outsideTheSegment(surface, ray, out.t);
        }
        if (surface instanceof TriangleSurface) {
            return outsideTheTriangle(out.beta, out.gamma);
        }
        return null;
    }

    /**
     * Why intersect returned false although it wrote a hit into the record ({@code before}: the record
     * as it was), or null when the record is as it was. A group that returns whether the last child
     * it tried was hit does exactly this whenever an earlier child was the hit.
     */
    public static String forHitLeftInTheRecord(Surface surface, Ray ray, IntersectionRecord before, IntersectionRecord out) {
        if (out.surface == before.surface && Double.compare(out.t, before.t) == 0) {
            return null;
        }
        String wrote = "it returned false, yet wrote a hit into the record (t = " + HitMessages.number(out.t)
                + (out.surface != null ? ", " + out.surface : "") + ")";
        if (!(ray.start < out.t && out.t < ray.end)) {
            return wrote + ", and " + outsideTheSegment(surface, ray, out.t);
        }
        return wrote + (surface instanceof Group
                ? ": a group returns whether any child was hit; does yours return whether the last child it tried was?"
                : ": intersect returns true exactly when it fills the record");
    }

    /** That t lies outside the ray's segment; for a group, that it must search the caller's segment. */
    private static String outsideTheSegment(Surface surface, Ray ray, double t) {
        String outside = "t = " + HitMessages.number(t) + " is not inside the ray's segment (" + HitMessages.number(ray.start)
                + ", " + HitMessages.number(ray.end) + "), whose ends are both excluded";
        return surface instanceof Group ? outside + ": a group searches the caller's segment, giving its children a copy of"
                + " the caller's ray (the same ray.start and ray.end), shortened as hits are found, not a segment of its own" : outside;
    }

    /** Which barycentric bound (β ≥ 0, γ ≥ 0, β + γ ≤ 1) a point breaks, or null if it is inside. */
    static String outsideTheTriangle(double beta, double gamma) {
        String bound = beta < 0 ? "β = " + HitMessages.number(beta) + " < 0"
                : gamma < 0 ? "γ = " + HitMessages.number(gamma) + " < 0"
                : beta + gamma > 1 ? "β + γ = " + HitMessages.number(beta + gamma) + " > 1"
                : null;
        return bound == null ? null : bound + ", so that point is outside the triangle";
    }

    /** Names the root {@code actual} is when the sphere's two roots are {@code expected} and {@code actual}. */
    private static String otherRoot(SphereSurface sphere, Ray ray, double expected, double actual) {
        Vec3 d = ray.direction;
        Vec3 f = ray.origin.minus(sphere.getCenter());
        double a = d.dot(d);
        double halfB = d.dot(f);
        double c = f.dot(f) - sphere.getRadius() * sphere.getRadius();
        double discriminant = halfB * halfB - a * c;
        if (!(discriminant > 0)) {
            return null;
        }
        double near = (-halfB - Math.sqrt(discriminant)) / a;
        double far = (-halfB + Math.sqrt(discriminant)) / a;
        if (same(actual, far) && same(expected, near) && !same(near, far)) {
            return "that is the far root, where the ray leaves the sphere, not the near one (t = " + HitMessages.number(near)
                    + "), which is inside the ray's segment and comes first";
        }
        if (same(actual, near) && same(expected, far) && !same(near, far)) {
            return "that is the near root, which is not inside the ray's segment (" + HitMessages.number(ray.start) + ", "
                    + HitMessages.number(ray.end) + "), so the hit is the far root";
        }
        return null;
    }

    private static boolean same(double x, double y) {
        return Math.abs(x - y) <= SAME * Math.max(Math.abs(x), Math.abs(y));
    }
}
