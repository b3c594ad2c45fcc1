package ray.bvh;

import ray.Ray;
import ray.math.Vec3;

/** Known wrong: the box counts only when the ray enters it within its segment, so a ray that starts inside a box (a camera inside a mesh, a shadow ray leaving a surface) skips it. */
public class BoundingBoxes extends BoxGeometry {

    public Box ofSphere(Vec3 center, double radius) {
        Vec3 reach = new Vec3(radius, radius, radius);
        return new Box(center.minus(reach), center.plus(reach));
    }

    public Box ofTriangle(Vec3 a, Vec3 b, Vec3 c) {
        Vec3 min = new Vec3(Math.min(a.x, Math.min(b.x, c.x)), Math.min(a.y, Math.min(b.y, c.y)), Math.min(a.z, Math.min(b.z, c.z)));
        Vec3 max = new Vec3(Math.max(a.x, Math.max(b.x, c.x)), Math.max(a.y, Math.max(b.y, c.y)), Math.max(a.z, Math.max(b.z, c.z)));
        return new Box(min, max);
    }

    public Box ofCylinder(Vec3 center, double radius, double height) {
        return new Box(new Vec3(center.x - radius, center.y, center.z - radius),
                new Vec3(center.x + radius, center.y + height, center.z + radius));
    }

    public boolean hit(Box box, Ray ray) {
        double near = Double.NEGATIVE_INFINITY;
        double far = ray.end;
        for (int axis = 0; axis < 3; axis++) {
            double inverse = 1 / ray.direction.get(axis);
            double origin = ray.origin.get(axis);
            double t0 = (box.min.get(axis) - origin) * inverse;
            double t1 = (box.max.get(axis) - origin) * inverse;
            if (t0 > t1) {
                double swap = t0;
                t0 = t1;
                t1 = swap;
            }
            t1 *= 1 + 2 * GAMMA_3;
            near = t0 > near ? t0 : near;
            far = t1 < far ? t1 : far;
        }
        return near >= ray.start && near <= far;
    }
}
