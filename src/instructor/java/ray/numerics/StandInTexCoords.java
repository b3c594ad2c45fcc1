package ray.numerics;

import ray.IntersectionRecord;
import ray.math.Vec3;
import ray.surface.TriangleSurface;

/**
 * The texture coordinates the stand-ins report, by the same conventions as the solution's Sphere and
 * Triangle, so that a sweep over float or textbook arithmetic changes where a hit is, not how a
 * texture is laid on it.
 */
final class StandInTexCoords {
    private StandInTexCoords() {
    }

    /** Longitude and latitude of a sphere's unit outward normal n: u = ½ + atan2(x, z)/2π, v = ½ + asin(y)/π. */
    static void sphere(IntersectionRecord out, Vec3 n) {
        out.texU = 0.5 + Math.atan2(n.x, n.z) / (2 * Math.PI);
        out.texV = 0.5 + Math.asin(Math.max(-1, Math.min(1, n.y))) / Math.PI;
    }

    /** The corners' coordinates blended by the barycentric weights. */
    static void triangle(IntersectionRecord out, TriangleSurface triangle, double beta, double gamma) {
        double alpha = 1 - beta - gamma;
        out.texU = alpha * triangle.getVt0().x + beta * triangle.getVt1().x + gamma * triangle.getVt2().x;
        out.texV = alpha * triangle.getVt0().y + beta * triangle.getVt1().y + gamma * triangle.getVt2().y;
    }
}
