package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The textbook quadratic: b² − 4ac, roots (−b ∓ √disc)/2a. */
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
        double a = d.dot(d);
        double b = 2 * d.dot(ec);
        double c = ec.dot(ec) - radius * radius;
        double disc = b * b - 4 * a * c;
        if (disc < 0) {
            return false;
        }
        double sqrtDisc = Math.sqrt(disc);
        double t = (-b - sqrtDisc) / (2 * a);
        if (t <= ray.start || t >= ray.end) {
            t = (-b + sqrtDisc) / (2 * a);
            if (t <= ray.start || t >= ray.end) {
                return false;
            }
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = out.location.minus(center).times(1 / radius);
        out.surface = this;
        // The textbook's (φ + π)/2π and (θ + π/2)/π, asin unclamped as students write it.
        out.texU = (Math.atan2(out.normal.x, out.normal.z) + Math.PI) / (2 * Math.PI);
        out.texV = (Math.asin(out.normal.y) + Math.PI / 2) / Math.PI;
        return true;
    }
}
