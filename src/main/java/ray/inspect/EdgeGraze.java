package ray.inspect;

import ray.Ray;
import ray.math.Vec3;
import ray.surface.TriangleSurface;

/**
 * Whether a ray a triangle's test missed passes within rounding of one of its edges. There the
 * test may round the ray to either side, so two triangles that share the edge can both miss it
 * and leave a crack pixel; a correct render has a few (the render tests allow them). The trace
 * says so beside such a miss instead of leaving a student to hunt for a mistake that is not there.
 * The barycentric coordinates of the ray's meeting with the triangle's plane are computed here in
 * double with the triangle's own vertices (Cramer's rule), independent of the student's test.
 */
final class EdgeGraze {
    /** How close to 0 a barycentric coordinate counts as "on the edge": far below a pixel, far above rounding (~1e-16). */
    static final double WITHIN = 1e-9;

    private EdgeGraze() {
    }

    /**
     * The edge of {@code triangle} that {@code ray} (in the triangle's coordinates) passes within
     * rounding of, inside its segment, as "v1–v2", or null when it passes none.
     */
    static String edge(TriangleSurface triangle, Ray ray) {
        Vec3 a = triangle.getV0();
        Vec3 e1 = a.minus(triangle.getV1());
        Vec3 e2 = a.minus(triangle.getV2());
        Vec3 d = ray.direction;
        Vec3 r = a.minus(ray.origin);
        double det = e1.dot(e2.cross(d));
        if (!(Math.abs(det) > 0)) {
            return null;
        }
        double beta = r.dot(e2.cross(d)) / det;
        double gamma = e1.dot(r.cross(d)) / det;
        double t = e1.dot(e2.cross(r)) / det;
        double alpha = 1 - beta - gamma;
        if (!(t > ray.start && t < ray.end) || Math.min(alpha, Math.min(beta, gamma)) < -WITHIN) {
            return null;
        }
        if (Math.abs(alpha) <= WITHIN) {
            return "v1–v2";
        }
        if (Math.abs(beta) <= WITHIN) {
            return "v0–v2";
        }
        if (Math.abs(gamma) <= WITHIN) {
            return "v0–v1";
        }
        return null;
    }

    /** The edge a missed primitive's ray grazes, or null (also for a hit, or a primitive that is no triangle). */
    static String ofMiss(ProbeNode p) {
        if (p.test == null || p.test.hit || p.test.failure != null || !(p.surface instanceof TriangleSurface)) {
            return null;
        }
        return edge((TriangleSurface) p.surface, p.ray);
    }
}
