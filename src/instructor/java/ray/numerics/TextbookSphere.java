package ray.numerics;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Surface;

/**
 * The textbook ray–sphere intersection, kept only to measure what the robust solution fixes:
 * discriminant b² − 4ac, roots (−b ± √Δ)/2a, hit point ray.pointAt(t) with no re-projection.
 *
 * <p>Never ships: it is the Task 2 answer (brief of issue 4). Far from the sphere, b² and 4ac are
 * huge and nearly equal, so Δ loses its low digits to cancellation; near a huge sphere, −b and √Δ
 * nearly cancel in the near root.
 */
final class TextbookSphere extends Surface {
    private final Vec3 center;
    private final double radius;

    TextbookSphere(Vec3 center, double radius) {
        this.center = center;
        this.radius = radius;
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Vec3 d = ray.direction;
        Vec3 f = ray.origin.minus(center);
        double a = d.dot(d);
        double b = 2 * d.dot(f);
        double c = f.dot(f) - radius * radius;
        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return false;
        }
        double root = Math.sqrt(discriminant);
        double tNear = (-b - root) / (2 * a);
        double tFar = (-b + root) / (2 * a);
        double t;
        if (tNear > ray.start && tNear < ray.end) {
            t = tNear;
        } else if (tFar > ray.start && tFar < ray.end) {
            t = tFar;
        } else {
            return false;
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = out.location.minus(center).times(1 / radius);
        out.surface = this;
        StandInTexCoords.sphere(out, out.normal);
        return true;
    }
}
