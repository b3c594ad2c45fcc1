package ray.numerics;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Triangle;

/**
 * Textbook ray–triangle tests, kept only to measure what the watertight solution fixes. Never
 * ships: Cramer's rule is the Task 3 answer (brief of issue 4).
 *
 * <p>Both solve p + t·d = v0 + β·(v1 − v0) + γ·(v2 − v0) and accept β ≥ 0, γ ≥ 0, β + γ ≤ 1. Each
 * of β and γ comes from its own rounded triple product, so for a ray through an edge shared by two
 * triangles the two triangles round their edge coordinate independently: both may land a hair
 * outside, and the ray passes between them. The optional absolute epsilon on the determinant (a
 * common "parallel ray" guard) also throws away every small triangle, since det scales with the
 * triangle's area times |d|.
 */
public final class TextbookTriangles {
    /** The absolute determinant threshold that textbooks and tutorials often use. */
    static final double TEXTBOOK_EPSILON = 1e-8;

    /** One ray–triangle test: fills out (t, location, normal, surface, β, γ) on a hit, as Surface.intersect does. */
    public interface Method {
        boolean intersect(Triangle triangle, IntersectionRecord out, Ray ray);
    }

    /** The solution's watertight test (Woop, Benthin and Wald 2013). */
    static final Method ROBUST = (triangle, out, ray) -> triangle.intersect(out, ray);
    /** Möller–Trumbore with det == 0 as the only parallel test. */
    public static final Method MOLLER_TRUMBORE = (triangle, out, ray) -> mollerTrumbore(triangle, out, ray, 0);
    /** Möller–Trumbore with the textbook early-out |det| &lt; 1e-8. */
    static final Method MOLLER_TRUMBORE_EPSILON = (triangle, out, ray) -> mollerTrumbore(triangle, out, ray, TEXTBOOK_EPSILON);
    /** Cramer's rule on the 3×3 system (Shirley and Marschner, Fundamentals of Computer Graphics §4.4.2). */
    public static final Method CRAMER = TextbookTriangles::cramer;

    private TextbookTriangles() {
    }

    /**
     * Möller and Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", JGT 2(1), 1997: β, γ
     * and t as triple products with the edges e1 = v1 − v0, e2 = v2 − v0 over det = e1·(d × e2).
     * A |det| at or below {@code epsilon} counts as a parallel ray.
     */
    static boolean mollerTrumbore(Triangle triangle, IntersectionRecord out, Ray ray, double epsilon) {
        Vec3 v0 = triangle.getV0();
        Vec3 e1 = triangle.getV1().minus(v0);
        Vec3 e2 = triangle.getV2().minus(v0);
        Vec3 pvec = ray.direction.cross(e2);
        double det = e1.dot(pvec);
        if (det == 0 || Math.abs(det) < epsilon) {
            return false;
        }
        double invDet = 1 / det;
        Vec3 tvec = ray.origin.minus(v0);
        double beta = tvec.dot(pvec) * invDet;
        if (beta < 0 || beta > 1) {
            return false;
        }
        Vec3 qvec = tvec.cross(e1);
        double gamma = ray.direction.dot(qvec) * invDet;
        if (gamma < 0 || beta + gamma > 1) {
            return false;
        }
        double t = e2.dot(qvec) * invDet;
        return accept(triangle, out, ray, t, beta, gamma);
    }

    /**
     * Cramer's rule on β·(v0 − v1) + γ·(v0 − v2) + t·d = v0 − p, each unknown its own determinant
     * over det = |v0 − v1, v0 − v2, d|, with det == 0 as the only parallel test.
     */
    static boolean cramer(Triangle triangle, IntersectionRecord out, Ray ray) {
        Vec3 a = triangle.getV0().minus(triangle.getV1());
        Vec3 b = triangle.getV0().minus(triangle.getV2());
        Vec3 d = ray.direction;
        Vec3 r = triangle.getV0().minus(ray.origin);
        double det = determinant(a, b, d);
        if (det == 0) {
            return false;
        }
        double beta = determinant(r, b, d) / det;
        double gamma = determinant(a, r, d) / det;
        double t = determinant(a, b, r) / det;
        if (!(beta >= 0 && gamma >= 0 && beta + gamma <= 1)) {
            return false;
        }
        return accept(triangle, out, ray, t, beta, gamma);
    }

    /** The determinant of the 3×3 matrix with columns c0, c1, c2, expanded along the first column. */
    private static double determinant(Vec3 c0, Vec3 c1, Vec3 c2) {
        return c0.x * (c1.y * c2.z - c1.z * c2.y) + c0.y * (c1.z * c2.x - c1.x * c2.z) + c0.z * (c1.x * c2.y - c1.y * c2.x);
    }

    private static boolean accept(Triangle triangle, IntersectionRecord out, Ray ray, double t, double beta, double gamma) {
        if (!(t > ray.start && t < ray.end)) {
            return false;
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = triangle.normalAt(beta, gamma);
        out.surface = triangle;
        out.beta = beta;
        out.gamma = gamma;
        StandInTexCoords.triangle(out, triangle, beta, gamma);
        return true;
    }
}
