package ray.bvh;

import ray.Ray;
import ray.math.Vec3;

/**
 * Correct: boxes as unions of one-point boxes, and the slab test written axis by axis, a zero
 * direction component handled by its own branch (inside the slab or not) rather than through NaN,
 * and the far distance widened by a few units in the last place.
 */
public class BoundingBoxes extends BoxGeometry {

    public Box ofSphere(Vec3 center, double radius) {
        return new Box(new Vec3(center.x - radius, center.y - radius, center.z - radius),
                new Vec3(center.x + radius, center.y + radius, center.z + radius));
    }

    public Box ofTriangle(Vec3 a, Vec3 b, Vec3 c) {
        return new Box(a, a).union(new Box(b, b)).union(new Box(c, c));
    }

    public Box ofCylinder(Vec3 center, double radius, double height) {
        Vec3 across = new Vec3(radius, 0, radius);
        return new Box(center.minus(across), center.plus(across).plus(new Vec3(0, height, 0)));
    }

    public boolean hit(Box box, Ray ray) {
        double tEnter = ray.start;
        double tLeave = ray.end;
        double[] o = {ray.origin.x, ray.origin.y, ray.origin.z};
        double[] d = {ray.direction.x, ray.direction.y, ray.direction.z};
        double[] lo = {box.min.x, box.min.y, box.min.z};
        double[] hi = {box.max.x, box.max.y, box.max.z};
        for (int i = 0; i < 3; i++) {
            if (d[i] == 0) {
                if (o[i] < lo[i] || o[i] > hi[i]) {
                    return false;
                }
                continue;
            }
            double a = (lo[i] - o[i]) / d[i];
            double b = (hi[i] - o[i]) / d[i];
            double near = Math.min(a, b);
            double far = Math.max(a, b) * (1 + 4 * Math.ulp(1.0));
            tEnter = Math.max(tEnter, near);
            tLeave = Math.min(tLeave, far);
            if (tEnter > tLeave) {
                return false;
            }
        }
        return true;
    }
}
