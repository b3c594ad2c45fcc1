package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: gives the normal as hit − center without dividing by the radius, so it is r long and a sphere of radius r is shaded r times too bright or too dark. */
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
        double t = (-b - Math.sqrt(disc)) / (2 * a);
        if (t <= ray.start || t >= ray.end) {
            t = (-b + Math.sqrt(disc)) / (2 * a);
            if (t <= ray.start || t >= ray.end) {
                return false;
            }
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = out.location.minus(center);
        out.surface = this;
        Vec3 unit = out.normal.times(1 / radius);
        out.texU = 0.5 + Math.atan2(unit.x, unit.z) / (2 * Math.PI);
        out.texV = 0.5 + Math.asin(Math.max(-1, Math.min(1, unit.y))) / Math.PI;
        return true;
    }
}
