package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Textbook roots, both computed and sorted, the hit built in a record of its own and copied with out.set. */
public class Sphere extends SphereSurface {
    public Sphere() {
    }

    public Sphere(Vec3 center, double radius) {
        setCenter(center);
        setRadius(radius);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Vec3 p = ray.origin;
        Vec3 d = ray.direction;
        double a = d.dot(d);
        double b = 2 * d.dot(p.minus(center));
        double c = p.minus(center).dot(p.minus(center)) - radius * radius;
        double disc = b * b - 4 * a * c;
        if (disc < 0) {
            return false;
        }
        double[] roots = {(-b - Math.sqrt(disc)) / (2 * a), (-b + Math.sqrt(disc)) / (2 * a)};
        java.util.Arrays.sort(roots);
        for (double t : roots) {
            if (t > ray.start && t < ray.end) {
                IntersectionRecord hit = new IntersectionRecord();
                hit.t = t;
                hit.location = p.plus(d.times(t));
                hit.normal = hit.location.minus(center).normalized();
                hit.surface = this;
                // Latitude as atan2(y, √(x² + z²)), which needs no clamping.
                Vec3 offset = hit.location.minus(center);
                hit.texU = 0.5 + Math.atan2(offset.x, offset.z) / (2 * Math.PI);
                hit.texV = 0.5 + Math.atan2(offset.y, Math.hypot(offset.x, offset.z)) / Math.PI;
                out.set(hit);
                return true;
            }
        }
        return false;
    }
}
