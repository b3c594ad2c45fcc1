package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The textbook way: (−b ∓ √(b² − 4ac))/2a for the side, one plane per cap, the least t kept in a local. */
public class Cylinder extends CylinderSurface {
    public Cylinder() {
    }

    public Cylinder(Vec3 center, double radius, double height) {
        setCenter(center);
        setRadius(radius);
        setHeight(height);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Vec3 p = ray.origin;
        Vec3 d = ray.direction;
        double px = p.x - center.x;
        double py = p.y - center.y;
        double pz = p.z - center.z;
        double best = Double.POSITIVE_INFINITY;
        Vec3 n = null;
        double a = d.x * d.x + d.z * d.z;
        double b = 2 * (px * d.x + pz * d.z);
        double c = px * px + pz * pz - radius * radius;
        double disc = b * b - 4 * a * c;
        if (a != 0 && disc >= 0) {
            double[] roots = {(-b - Math.sqrt(disc)) / (2 * a), (-b + Math.sqrt(disc)) / (2 * a)};
            for (double t : roots) {
                double y = py + t * d.y;
                if (t > ray.start && t < ray.end && t < best && y >= 0 && y <= height) {
                    best = t;
                    double x = px + t * d.x;
                    double z = pz + t * d.z;
                    n = new Vec3(x / radius, 0, z / radius);
                }
            }
        }
        double[] planes = {0, height};
        for (double plane : planes) {
            if (d.y == 0) {
                continue;
            }
            double t = (plane - py) / d.y;
            double x = px + t * d.x;
            double z = pz + t * d.z;
            if (t > ray.start && t < ray.end && t < best && x * x + z * z <= radius * radius) {
                best = t;
                n = new Vec3(0, plane == 0 ? -1 : 1, 0);
            }
        }
        if (n == null) {
            return false;
        }
        out.t = best;
        out.location = ray.pointAt(best);
        out.normal = n;
        out.surface = this;
        return true;
    }
}
