package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: assumes the ray's direction has unit length (a = 1 instead of d·d), so t is off for any other direction. */
public class Sphere extends SphereSurface {
    public Sphere() {
    }

    public Sphere(Vec3 center, double radius) {
        setCenter(center);
        setRadius(radius);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Vec3 d = ray.direction;
        Vec3 ec = ray.origin.minus(center);
        double a = 1;
        double b = 2 * d.dot(ec);
        double c = ec.dot(ec) - radius * radius;
        double disc = b * b - 4 * a * c;
        if (disc < 0) {
            return false;
        }
        double t = (-b - Math.sqrt(disc)) / (2 * a);
        if (t <= ray.start || t >= ray.end) {
            t = (-b + Math.sqrt(disc)) / (2 * a);
            if (t <= ray.start || t >= ray.end) {
                return false;
            }
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = out.location.minus(center).times(1 / radius);
        out.surface = this;
        out.texU = 0.5 + Math.atan2(out.normal.x, out.normal.z) / (2 * Math.PI);
        out.texV = 0.5 + Math.asin(Math.max(-1, Math.min(1, out.normal.y))) / Math.PI;
        return true;
    }
}
