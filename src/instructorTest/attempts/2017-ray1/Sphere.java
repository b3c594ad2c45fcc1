package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

public class Sphere extends SphereSurface {
    public Sphere() {
    }

    public Sphere(Vec3 center, double radius) {
        setCenter(center);
        setRadius(radius);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Vec3 oc = ray.origin.minus(center);
        double b = 2 * ray.direction.dot(oc);
        double c = oc.dot(oc) - radius * radius;
        double disc = b * b - 4 * c;
        if (disc < 0) {
            return false;
        }
        double t = (-b - Math.sqrt(disc)) / 2;
        Vec3 hit = ray.origin.plus(ray.direction.times(t));
        Vec3 n = hit.minus(center).times(1 / radius);
        out.t = t;
        out.location = hit;
        out.normal = n;
        out.surface = this;
        out.texU = 0.5 + Math.atan2(n.x, n.z) / (2 * Math.PI);
        out.texV = 0.5 + Math.asin(n.y) / Math.PI;
        return true;
    }
}
