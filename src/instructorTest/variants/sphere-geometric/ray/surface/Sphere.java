package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The lecture's geometric test: unit direction, closest approach, t rescaled to the ray's own direction. */
public class Sphere extends SphereSurface {
    public Sphere() {
    }

    public Sphere(Vec3 center, double radius) {
        setCenter(center);
        setRadius(radius);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        double length = ray.direction.length();
        Vec3 dHat = ray.direction.times(1 / length);
        Vec3 toCenter = center.minus(ray.origin);
        double tca = toCenter.dot(dHat);
        double d2 = toCenter.dot(toCenter) - tca * tca;
        if (d2 > radius * radius) {
            return false;
        }
        double thc = Math.sqrt(radius * radius - d2);
        // Distances along the unit direction; t for the ray's own direction is distance / |d|.
        double t0 = (tca - thc) / length;
        double t1 = (tca + thc) / length;
        double t;
        if (t0 > ray.start && t0 < ray.end) {
            t = t0;
        } else if (t1 > ray.start && t1 < ray.end) {
            t = t1;
        } else {
            return false;
        }
        out.t = t;
        out.location = ray.pointAt(t);
        out.normal = out.location.minus(center).times(1 / radius);
        out.surface = this;
        // Texture coordinates from the un-normalized offset; v by acos: 1 − acos(y)/π = ½ + asin(y)/π.
        Vec3 offset = out.location.minus(center);
        out.texU = Math.atan2(offset.x, offset.z) / (2 * Math.PI) + 0.5;
        out.texV = 1 - Math.acos(Math.max(-1, Math.min(1, offset.y / radius))) / Math.PI;
        return true;
    }
}
