package ray.inspect;

import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Surface;

/**
 * What a hit record claims, checked against the intersect contract: its t lies inside the ray's
 * segment (start, end), its normal has unit length, and what its own surface checks (a sphere seen
 * from outside is hit where the ray enters it). A surface that ignores ray.start reports
 * hits behind a shadow ray's start (a point shadowed by what lies behind it); one that assumes a
 * unit direction reports normals of any length, which the shading then takes as unit ones.
 */
final class RecordChecks {
    /** How far from 1 a normal's length may be: rounding of a normalize() is some 1e-16. */
    static final double UNIT_TOLERANCE = 1e-6;

    private RecordChecks() {
    }

    /** Every check of a camera ray's closest hit that fails, in the order the trace prints them. */
    static List<String> of(IntersectionRecord hit, Ray ray) {
        List<String> flags = new ArrayList<>();
        for (String flag : new String[] {outsideSegment(hit.t, ray, "camera ray"), notUnit(hit.normal), shapeDoubt(hit, ray)}) {
            if (flag != null) {
                flags.add(flag);
            }
        }
        return flags;
    }

    /**
     * Why t cannot be a hit on {@code ray} (named {@code rayName}, "shadow ray"), or null when it
     * lies in the segment: "t = −9.5 lies behind the shadow ray's start (0): …".
     */
    static String outsideSegment(double t, Ray ray, String rayName) {
        if (Double.isNaN(t)) {
            return "t is NaN: a hit must lie in the ray's segment (start, end)";
        }
        if (t <= ray.start) {
            return "t = " + Fmt.num(t) + " lies behind the " + rayName + "'s start (" + Fmt.num(ray.start)
                    + "): a hit must lie in (start, end); does that intersect check ray.start?";
        }
        if (t >= ray.end) {
            return "t = " + Fmt.num(t) + " lies beyond the " + rayName + "'s end (" + Fmt.num(ray.end)
                    + "): a hit must lie in (start, end); does that intersect check ray.end?";
        }
        return null;
    }

    /** What the hit's own surface finds wrong with it ({@link Surface#doubtAbout}), or null. */
    static String shapeDoubt(IntersectionRecord hit, Ray ray) {
        return hit.surface == null || hit.normal == null || hit.location == null ? null : hit.surface.doubtAbout(hit, ray);
    }

    /** Why {@code normal} is no unit normal, or null when its length is 1: "not unit length: |n| = 2.4691; …". */
    static String notUnit(Vec3 normal) {
        if (normal == null) {
            return null;
        }
        double length = normal.length();
        if (Math.abs(length - 1) <= UNIT_TOLERANCE) {
            return null;
        }
        return "the normal is not unit length: |n| = " + Fmt.num(length) + "; the shading takes it as a unit vector,"
                + " so n·l and the highlight come out scaled: normalize it";
    }
}
