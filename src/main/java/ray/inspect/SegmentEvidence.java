package ray.inspect;

import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.Surface;
import ray.surface.SurfaceKind;

/**
 * The evidence to weigh before a group is blamed for returning a hit that is not the closest. A
 * group loop keeps the closest hit by shortening the ray to end at each hit's t, so every primitive
 * it asks after the closest one sees a segment ending there, and must then report no hit: a
 * primitive that ignores ray.end claims its farther hit anyway and replaces the closer one, and the
 * group, though right, returns a wrong hit. So each primitive is asked again, alone, with the
 * segment the group gives it once it holds the closest hit (end = that hit's t); a primitive that
 * claims a hit outside that segment, or a t other than the one it reports on the whole ray, is
 * named with its task. Only when every primitive answers right is the group to blame.
 */
final class SegmentEvidence {
    private SegmentEvidence() {
    }

    /**
     * The primitive whose answer on the shortened segment breaks the intersect contract, in one
     * line ("! #1 Mesh … › triangle #3 reports a hit at t = 5.2 …. See TODO(Task 3)"), or null
     * when every one answers as the contract says. {@code returned} is the surface the group's
     * record names: it is asked first, since it is the likeliest to have replaced the closest hit.
     */
    static String culprit(List<ProbeNode> roots, ProbeNode nearest, Surface returned, SurfaceNames names) {
        List<ProbeNode> primitives = new ArrayList<>(ProbeTree.primitives(roots));
        ProbeNode first = ProbeTree.bySurface(primitives, returned);
        if (first != null) {
            primitives.remove(first);
            primitives.add(0, first);
        }
        double end = nearest.t();
        for (ProbeNode p : primitives) {
            String problem = answerOnSegment(p, end);
            if (problem != null) {
                int task = SurfaceKind.of(p.surface).task();
                String method = p.surface.getClass().getSimpleName() + ".intersect";
                return "! " + ProbeTree.path(roots, p, names) + " " + problem + ", the segment a group gives it once it holds the"
                        + " closest hit (t = " + Fmt.num(end) + ", at " + ProbeTree.path(roots, nearest, names) + "): a hit must lie in"
                        + " (start, end), or it replaces the closer hit the group keeps. Does " + method + " check ray.end?"
                        + (task > 0 ? " See TODO(Task " + task + ")" : "");
            }
        }
        return null;
    }

    /** What is wrong with p's answer on its own ray cut to end at {@code end}, or null when nothing is. */
    private static String answerOnSegment(ProbeNode p, double end) {
        Ray cut = new Ray(p.ray.origin, p.ray.direction, p.ray.start, end);
        IntersectionRecord record = new IntersectionRecord();
        boolean hit;
        try {
            hit = p.surface.intersect(record, cut);
        } catch (RuntimeException | StackOverflowError e) {
            return null; // an exception is reported where the primitive is listed
        }
        if (!hit) {
            return null;
        }
        if (!(record.t > cut.start && record.t < cut.end)) {
            return "reports a hit at t = " + Fmt.num(record.t) + " on the ray cut to (" + Fmt.num(cut.start) + ", " + Fmt.num(end) + ")";
        }
        if (p.isHit() && record.t != p.t()) {
            return "reports t = " + Fmt.num(record.t) + " on the ray cut to (" + Fmt.num(cut.start) + ", " + Fmt.num(end)
                    + "), but t = " + Fmt.num(p.t()) + " on the whole ray";
        }
        return null;
    }
}
