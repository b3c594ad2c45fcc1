package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** A sphere: the points at distance {@code radius} from {@code center} (both kept by SphereSurface). */
public class Sphere extends SphereSurface {

    public Sphere() {
    }

    public Sphere(Vec3 center, double radius) {
        setCenter(center);
        setRadius(radius);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        // TODO(Task 2): intersect the ray with this sphere.
        //   Return whether the ray meets the sphere, and on a hit fill out with the nearest hit: its t, its
        //   location, the unit outward normal, this surface and its texture coordinates. On a miss leave out
        //   exactly as it was.
        //   Conventions (the reference images depend on them):
        //   - The hit counts only for ray.start < t < ray.end, both ends open, with t the ray's own
        //     parameter (its direction is not unit length).
        //   - The texture coordinates come from the unit normal (x, y, z), y toward the north pole:
        //     out.texU = ½ + atan2(x, z)/(2π) (0 to 1 around the pole) and out.texV = ½ + asin(y)/π
        //     (0 at the south pole, 1 at the north).
        // HINTS steps
        //   1) Write the points of the ray into the sphere's equation: it becomes a quadratic equation in t.
        //   2) When it has no real roots the ray misses.
        //   3) Of its roots, take the smallest one inside the ray's open segment; none means a miss.
        //   4) On a hit fill the record (t, the point, the unit outward normal, this) and return true.
        //   5) Fill the texture coordinates from the unit normal, as the conventions say.
        // HINTS formulas
        //   1) Put r(t) = p + t·d into |x − center|² = radius² and expand: a t² + b t + c = 0 with
        //      a = d·d, b = 2 d·(p − center), c = (p − center)·(p − center) − radius².
        //   2) A negative discriminant b² − 4ac means the ray misses.
        //   3) Of the two roots, take the smallest t with ray.start < t < ray.end; none means a miss.
        //   4) On a hit fill out.t, out.location = ray.pointAt(t), out.normal = (location − center)/radius
        //      and out.surface = this, then return true. On a miss, return false and leave out alone.
        //   5) Also fill the texture coordinates from (x, y, z) = out.normal (unit length, y toward
        //      the north pole): out.texU = ½ + atan2(x, z)/(2π) (the longitude, 0 to 1 around the
        //      pole) and out.texV = ½ + asin(y)/π (the latitude, 0 at the south pole, 1 at the north).
        // END HINTS
        // BEGIN SOLUTION
        // The textbook discriminant b² − 4ac cancels catastrophically for small or far spheres.
        // Ray Tracing Gems ch. 7 computes it from the ray's closest-approach vector instead:
        // with f = p − c and d̂ = d/|d|, l = f − (f·d̂)d̂ and Δ/(4a) = r² − l·l.
        // Most rays miss most spheres, so the miss is decided first, from d̂.
        // A zero, NaN or infinite d puts a NaN in d̂ and so in the discriminant: a miss. A d whose
        // |d|² overflows has d̂ = 0 and is rejected just below.
        Vec3 f = ray.origin.minus(center);
        Vec3 unitD = ray.direction.times(1 / Math.sqrt(ray.direction.dot(ray.direction)));
        Vec3 l = f.minus(unitD.times(f.dot(unitD)));
        double discriminantOverA = radius * radius - l.dot(l);
        if (!(discriminantOverA >= 0)) {
            return false;
        }
        Vec3 d = ray.direction;
        double a = d.dot(d);
        if (!(a > 0) || Double.isInfinite(a)) {
            return false; // |d|² underflowed or overflowed: no usable root
        }
        double halfB = f.dot(d);
        double c = f.dot(f) - radius * radius;
        // Stable quadratic (Numerical Recipes §5.6): q = −(b' + sign(b')√Δ'), roots q/a and c/q,
        // so that the root near zero is never the difference of two nearly equal numbers.
        double rootDelta = Math.sqrt(a) * Math.sqrt(discriminantOverA);
        double q = -(halfB + Math.copySign(rootDelta, halfB));
        double t0 = q / a;
        double t1 = q != 0 ? c / q : t0;
        double tNear = Math.min(t0, t1);
        double tFar = Math.max(t0, t1);
        double t;
        if (tNear > ray.start && tNear < ray.end) {
            t = tNear;
        } else if (tFar > ray.start && tFar < ray.end) {
            t = tFar;
        } else {
            return false;
        }
        // Re-project the hit onto the sphere so that its distance from the center is radius
        // to rounding, whatever the error of t (Ray Tracing Gems ch. 6 and 7).
        Vec3 outward = ray.pointAt(t).minus(center).normalized();
        out.t = t;
        out.location = center.plusScaled(radius, outward);
        out.normal = outward;
        out.surface = this;
        // Longitude and latitude of the unit normal; clamped, since a rounded y may pass ±1 and
        // asin would give NaN.
        out.texU = 0.5 + Math.atan2(outward.x, outward.z) / (2 * Math.PI);
        out.texV = 0.5 + Math.asin(Math.max(-1, Math.min(1, outward.y))) / Math.PI;
        return true;
        // END SOLUTION
        // STUB: return false;
    }
}
