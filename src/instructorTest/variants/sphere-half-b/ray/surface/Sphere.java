package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Ray Tracing in One Weekend's form: b = 2h, so disc/4 = h² − ac and the roots are (−h ∓ √(h² − ac))/a. */
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
        double a = ray.direction.lengthSquared();
        double halfB = oc.dot(ray.direction);
        double c = oc.lengthSquared() - radius * radius;
        double discriminant = halfB * halfB - a * c;
        if (discriminant < 0) {
            return false;
        }
        double sqrtd = Math.sqrt(discriminant);
        double root = (-halfB - sqrtd) / a;
        if (!(ray.start < root && root < ray.end)) {
            root = (-halfB + sqrtd) / a;
            if (!(ray.start < root && root < ray.end)) {
                return false;
            }
        }
        out.t = root;
        out.location = ray.pointAt(root);
        out.normal = out.location.minus(center).normalized();
        out.surface = this;
        Vec3 n = out.normal;
        out.texU = 0.5 + Math.atan2(n.x, n.z) * (0.5 / Math.PI);
        out.texV = 0.5 + Math.asin(n.y) / Math.PI;
        return true;
    }
}
