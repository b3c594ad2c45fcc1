package ray.bvh;

import ray.Ray;
import ray.math.Vec3;

/** The boxes the hierarchy is built from, and the test of a ray against a box. */
public class BoundingBoxes extends BoxGeometry {

    public Box ofSphere(Vec3 center, double radius) {
        // TODO(Task 12): return the smallest box that holds the sphere.
        //   Conventions:
        //   - Every point of the sphere of this center and radius is in the box, and the box is no bigger
        //     than it needs to be.
        // HINTS steps
        //   1) The sphere reaches radius beyond its center along each axis, both ways.
        //   2) Make a box from those two corners.
        // HINTS formulas
        //   1) min = center − (r, r, r), max = center + (r, r, r).
        //   2) return new Box(min, max).
        // END HINTS
        // BEGIN SOLUTION
        Vec3 reach = new Vec3(radius, radius, radius);
        return new Box(center.minus(reach), center.plus(reach));
        // END SOLUTION
        // STUB: return null;
    }

    public Box ofTriangle(Vec3 a, Vec3 b, Vec3 c) {
        // TODO(Task 12): return the smallest box that holds the triangle a, b, c.
        //   Conventions:
        //   - The box holds the three corners and nothing more on any axis: a triangle that lies in a plane
        //     z = 2 has a flat box, with min.z = max.z = 2.
        //   - A degenerate triangle (its corners on one line, or all in one place) still gets the box of
        //     its corners.
        // HINTS steps
        //   1) On each axis, the box runs from the smallest of the three corners' coordinates to the
        //      largest.
        // HINTS formulas
        //   1) min = (min(a.x, b.x, c.x), min(a.y, b.y, c.y), min(a.z, b.z, c.z)); max the same with max.
        // END HINTS
        // BEGIN SOLUTION
        Vec3 min = new Vec3(Math.min(a.x, Math.min(b.x, c.x)), Math.min(a.y, Math.min(b.y, c.y)), Math.min(a.z, Math.min(b.z, c.z)));
        Vec3 max = new Vec3(Math.max(a.x, Math.max(b.x, c.x)), Math.max(a.y, Math.max(b.y, c.y)), Math.max(a.z, Math.max(b.z, c.z)));
        return new Box(min, max);
        // END SOLUTION
        // STUB: return null;
    }

    public Box ofCylinder(Vec3 center, double radius, double height) {
        // TODO(Task 12): return the smallest box that holds the capped cylinder (extra credit).
        //   The cylinder stands on its bottom cap, centered at center, and rises along +y by height; its
        //   side is radius from its axis.
        //   Conventions:
        //   - Both caps are in the box, and the box is no bigger than it needs to be.
        // HINTS steps
        //   1) Across the axis (x and z) it reaches radius to each side of the center.
        //   2) Along the axis (y) it runs from the bottom cap up to the top.
        // HINTS formulas
        //   1) min = (cx − r, cy, cz − r), max = (cx + r, cy + height, cz + r).
        // END HINTS
        // BEGIN SOLUTION
        return new Box(new Vec3(center.x - radius, center.y, center.z - radius),
                new Vec3(center.x + radius, center.y + height, center.z + radius));
        // END SOLUTION
        // STUB: return null;
    }

    public boolean hit(Box box, Ray ray) {
        // TODO(Task 12): return whether the ray passes through the box for some t in [ray.start, ray.end].
        //   The hierarchy skips everything inside a box this returns false for, so it must never return
        //   false for a box the ray does pass through; a true for a box the ray just misses costs only time.
        //   Conventions (the tests check each):
        //   - Faces count: a ray that only touches a face, an edge or a corner hits the box; so does a ray
        //     through a flat box (min = max on an axis).
        //   - A direction component may be 0 (the ray is parallel to two faces): then 1/d is ±infinity, and
        //     where the ray's origin lies in a face's plane, 0 · infinity is NaN.
        //   - A ray that starts inside the box hits it.
        //   - Rounding must not lose a hit: widen the far distance by its rounding error (GAMMA_3).
        // HINTS steps
        //   1) Keep an interval of t, starting as the ray's own, from ray.start to ray.end.
        //   2) On each axis, find where the ray crosses the box's two planes; the nearer of the two is where
        //      it enters the slab between them, the farther where it leaves.
        //   3) Narrow the interval to each slab's, comparing so that a NaN distance leaves it as it was.
        //   4) Widen each far distance by its rounding error first, so a hit on an edge is not rounded away.
        //   5) The ray hits the box when the interval is not empty at the end (its two ends may be equal).
        // HINTS formulas
        //   1) near = ray.start, far = ray.end.
        //   2) On axis i: t0 = (box.min_i − o_i) · (1/d_i), t1 = (box.max_i − o_i) · (1/d_i); swap if t0 > t1.
        //   3) t1 = t1 · (1 + 2 GAMMA_3).
        //   4) near = t0 > near ? t0 : near; far = t1 < far ? t1 : far (a comparison with NaN is false, so a
        //      NaN is ignored; Math.max and Math.min would return the NaN instead).
        //   5) return near ≤ far.
        // END HINTS
        // BEGIN SOLUTION
        double near = ray.start;
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
        return near <= far;
        // END SOLUTION
        // STUB: return false;
    }
}
