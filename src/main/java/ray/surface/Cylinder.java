package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Extra credit: a capped cylinder along +y. Its bottom cap is centered at {@code center}, its top
 * cap {@code height} above it, and its side is {@code radius} from the axis (all kept by
 * CylinderSurface).
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
        // TODO(Task 6): intersect the ray with this capped cylinder (extra credit).
        //   Return whether the ray meets this capped cylinder, and on a hit fill out with the nearest hit: its
        //   t, its location, the unit outward normal and this surface; on a miss leave out exactly as it was.
        //   Conventions (the reference images depend on them):
        //   - The hit counts only for ray.start < t < ray.end, both ends open, with t the ray's own
        //     parameter (its direction is not unit length).
        //   - The bottom cap's center is center, the cylinder rises along +y by height, and its radius is
        //     radius; the caps' normals are −y (bottom) and +y (top), the side's points straight away from
        //     the axis.
        // HINTS steps
        //   1) The side: the ray's points at the radius's distance from the axis give a quadratic in t that
        //      uses only x and z; keep the roots whose point lies between the caps.
        //   2) The caps: where the ray crosses each cap's plane, keep the point if it lies within the disc.
        //   3) Of all the candidates keep the smallest t inside the ray's segment; none means a miss.
        //   4) Fill the record with the outward normal of the part that was hit and return true.
        // HINTS formulas
        //   Work with f = p − center, so that the bottom cap lies in y = 0 and the top in y = height.
        //   1) The side: (fx + t dx)² + (fz + t dz)² = radius² is a quadratic a t² + b t + c = 0 in x
        //      and z only: a = dx² + dz², b = 2 (fx dx + fz dz), c = fx² + fz² − radius². When a = 0
        //      the ray runs parallel to the axis and meets no side. A root counts only where the
        //      point's y (fy + t dy) lies between 0 and height.
        //   2) The caps: when dy ≠ 0 the ray meets the plane y = 0 at t = −fy/dy and y = height at
        //      t = (height − fy)/dy; a cap is hit when that point's (x, z) is within radius of the axis.
        //   3) Of all these candidates, keep the smallest t with ray.start < t < ray.end; none: return
        //      false and leave out alone.
        //   4) Fill out.t, out.location = ray.pointAt(t), out.surface = this and the unit outward
        //      normal: (x − cx, 0, z − cz)/radius on the side, (0, −1, 0) on the bottom cap and
        //      (0, 1, 0) on the top; return true.
        // END HINTS
        // BEGIN SOLUTION
        Vec3 f = ray.origin.minus(center);
        Vec3 d = ray.direction;
        double bestT = ray.end;
        Vec3 bestNormal = null;
        // The side, with the sphere's stable forms in the xz-plane: the discriminant from the
        // closest approach of the projected line to the axis (Ray Tracing Gems ch. 7), and the
        // roots q/a and c/q (Numerical Recipes §5.6), so neither cancels for a far or thin cylinder.
        double a = d.x * d.x + d.z * d.z;
        if (a > 0 && !Double.isInfinite(a)) {
            double halfB = f.x * d.x + f.z * d.z;
            double along = halfB / a;
            double lx = f.x - along * d.x;
            double lz = f.z - along * d.z;
            double discriminantOverA = radius * radius - (lx * lx + lz * lz);
            if (discriminantOverA >= 0) {
                double c = f.x * f.x + f.z * f.z - radius * radius;
                double q = -(halfB + Math.copySign(Math.sqrt(a) * Math.sqrt(discriminantOverA), halfB));
                double t0 = q / a;
                double t1 = q != 0 ? c / q : t0;
                for (double t : new double[] {t0, t1}) {
                    double y = f.y + t * d.y;
                    if (t > ray.start && t < bestT && y >= 0 && y <= height) {
                        bestT = t;
                        bestNormal = null; // the side's normal is computed from the hit below
                    }
                }
            }
        }
        boolean sideHit = bestT < ray.end;
        // The caps: planes y = 0 (normal −y) and y = height (normal +y).
        if (d.y != 0) {
            for (int top = 0; top <= 1; top++) {
                double t = ((top == 1 ? height : 0) - f.y) / d.y;
                double x = f.x + t * d.x;
                double z = f.z + t * d.z;
                if (t > ray.start && t < bestT && x * x + z * z <= radius * radius) {
                    bestT = t;
                    bestNormal = new Vec3(0, top == 1 ? 1 : -1, 0);
                }
            }
        }
        if (bestNormal == null && !sideHit) {
            return false;
        }
        out.t = bestT;
        out.location = ray.pointAt(bestT);
        out.normal = bestNormal != null ? bestNormal
                : new Vec3(out.location.x - center.x, 0, out.location.z - center.z).normalized();
        out.surface = this;
        return true;
        // END SOLUTION
        // STUB: return false;
    }
}
