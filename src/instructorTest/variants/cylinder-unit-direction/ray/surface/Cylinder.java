package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Works along the unit direction (distances s = t·|d|), caps before the side, and the side's
 * normal from the hit point minus the axis point at its height, normalized.
 */
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
        double length = ray.direction.length();
        Vec3 u = ray.direction.normalized();
        Vec3 o = ray.origin.minus(center);
        double sMin = ray.start * length;
        double sMax = ray.end * length;
        double bestS = Double.NaN;
        boolean cap = false;
        boolean top = false;
        if (u.y != 0) {
            double sBottom = -o.y / u.y;
            double sTop = (height - o.y) / u.y;
            if (inDisc(o, u, sBottom) && sBottom > sMin && sBottom < sMax) {
                bestS = sBottom;
                cap = true;
            }
            if (inDisc(o, u, sTop) && sTop > sMin && sTop < sMax && !(sTop >= bestS)) {
                bestS = sTop;
                cap = true;
                top = true;
            }
        }
        double a = u.x * u.x + u.z * u.z;
        if (a > 0) {
            double halfB = o.x * u.x + o.z * u.z;
            double c = o.x * o.x + o.z * o.z - radius * radius;
            double disc = halfB * halfB - a * c;
            if (disc >= 0) {
                double root = Math.sqrt(disc);
                for (double s : new double[] {(-halfB - root) / a, (-halfB + root) / a}) {
                    double y = o.y + s * u.y;
                    if (s > sMin && s < sMax && y >= 0 && y <= height && !(s >= bestS)) {
                        bestS = s;
                        cap = false;
                    }
                }
            }
        }
        if (Double.isNaN(bestS)) {
            return false;
        }
        out.t = bestS / length;
        out.location = ray.pointAt(out.t);
        if (cap) {
            out.normal = top ? new Vec3(0, 1, 0) : new Vec3(0, -1, 0);
        } else {
            Vec3 axisPoint = new Vec3(center.x, out.location.y, center.z);
            out.normal = out.location.minus(axisPoint).normalized();
        }
        out.surface = this;
        return true;
    }

    private boolean inDisc(Vec3 o, Vec3 u, double s) {
        double x = o.x + s * u.x;
        double z = o.z + s * u.z;
        return x * x + z * z <= radius * radius;
    }
}
