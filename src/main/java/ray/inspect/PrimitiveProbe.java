package ray.inspect;

import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Surface;

/**
 * One primitive tested alone: its own intersect, a fresh record and a copy of the whole ray, so
 * that what it reports cannot depend on the other surfaces. Also checks the intersect contract
 * (a hit inside the segment, a filled record with a unit normal, an untouched record on a miss),
 * since a broken contract is what makes a student's picture wrong in ways that are hard to see.
 */
final class PrimitiveProbe {
    /** Whether intersect returned true. */
    final boolean hit;
    /** The record as intersect left it (in the coordinates of the ray it was given). */
    final IntersectionRecord record;
    /** The exception intersect threw, in one line, or null. */
    final String failure;
    /** Broken parts of the contract, each in one line. */
    final List<String> problems;

    private PrimitiveProbe(boolean hit, IntersectionRecord record, String failure, List<String> problems) {
        this.hit = hit;
        this.record = record;
        this.failure = failure;
        this.problems = problems;
    }

    static PrimitiveProbe run(Surface primitive, Ray ray) {
        IntersectionRecord record = new IntersectionRecord();
        Ray copy = ray.copy();
        boolean hit;
        try {
            hit = primitive.intersect(record, copy);
        } catch (RuntimeException | StackOverflowError e) {
            return new PrimitiveProbe(false, record, Failure.oneLine(e), List.of());
        }
        List<String> problems = hit ? hitProblems(primitive, ray, record) : missProblems(record);
        if (copy.start != ray.start || copy.end != ray.end) {
            problems.add("intersect changed the ray's segment to (" + Fmt.num(copy.start) + ", " + Fmt.num(copy.end)
                    + "): it should only read it");
        }
        return new PrimitiveProbe(hit, record, null, problems);
    }

    private static List<String> hitProblems(Surface primitive, Ray ray, IntersectionRecord r) {
        List<String> problems = new ArrayList<>();
        if (!(r.t > ray.start && r.t < ray.end)) {
            problems.add("returned true with t = " + Fmt.num(r.t) + ", outside the segment (" + Fmt.num(ray.start)
                    + ", " + Fmt.num(ray.end) + "): not counted as a hit");
        }
        if (r.location == null) {
            problems.add("returned true but left out.location unset");
        } else if (Double.isFinite(r.t)) {
            Vec3 onRay = ray.pointAt(r.t);
            double off = r.location.minus(onRay).length();
            if (!(off <= 1e-6 * (1 + onRay.maxAbs()))) {
                problems.add("out.location " + Fmt.vec(r.location) + " is not ray.pointAt(t) = " + Fmt.vec(onRay));
            }
        }
        if (r.normal == null) {
            problems.add("returned true but left out.normal unset");
        } else if (!(Math.abs(r.normal.length() - 1) <= 1e-6)) {
            problems.add("out.normal " + Fmt.vec(r.normal) + " has length " + Fmt.num(r.normal.length()) + ", not 1");
        }
        if (r.surface != primitive) {
            problems.add(r.surface == null ? "returned true but left out.surface unset (it should be this)"
                    : "out.surface is " + r.surface + ", not this " + primitive.getClass().getSimpleName());
        }
        return problems;
    }

    private static List<String> missProblems(IntersectionRecord r) {
        List<String> problems = new ArrayList<>();
        boolean untouched = r.t == Double.POSITIVE_INFINITY && r.location == null && r.normal == null
                && r.surface == null && r.beta == 0 && r.gamma == 0 && r.texU == 0 && r.texV == 0;
        if (!untouched) {
            problems.add("returned false but changed the record: a miss must leave it untouched, or a group's"
                    + " closest hit gets overwritten");
        }
        return problems;
    }
}
