package ray.trace;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;

/**
 * The shadow ray from a hit to one light, tested the two ways the camera ray is: against every
 * primitive alone (to name the blockers) and by the scene's group (what the renderer uses).
 */
final class ShadowCheck {
    private static final int MAX_BLOCKERS = 3;

    private ShadowCheck() {
    }

    /** Prints the shadow ray (the renderer's, from {@code tracer}) and what blocks it; returns whether the renderer sees the light as blocked. */
    static boolean print(Scene scene, SurfaceNames names, TraceTracer tracer, IntersectionRecord hit, Vec3 lightPosition,
            String indent, PrintWriter out) {
        Ray shadowRay = tracer.shadowRay(hit, lightPosition);
        out.println(Fmt.row(indent, "shadow ray", "from " + Fmt.vec(shadowRay.origin) + " (just off the surface) along "
                + Fmt.vec(shadowRay.direction) + ", t in (0, 1 − 1e-9)"));
        List<ProbeNode> roots = ProbeTree.of(scene.getSurfaces(), shadowRay);
        List<ProbeNode> blockers = new ArrayList<>();
        for (ProbeNode p : ProbeTree.primitives(roots)) {
            if (p.isHit()) {
                blockers.add(p);
            }
        }
        // Nearest blocker first: the one a student would see standing between the point and the light.
        blockers.sort((a, b) -> Double.compare(a.t(), b.t()));
        boolean blockedByGroup;
        try {
            blockedByGroup = scene.getSurfaces().intersect(new IntersectionRecord(), shadowRay.copy());
        } catch (RuntimeException | StackOverflowError e) {
            out.println(Fmt.row(indent, "shadow", "the scene's group threw " + Failure.oneLine(e)));
            return false;
        }
        if (blockers.isEmpty()) {
            out.println(Fmt.row(indent, "shadow", "not blocked: every surface misses the shadow ray"));
        }
        for (int k = 0; k < Math.min(MAX_BLOCKERS, blockers.size()); k++) {
            ProbeNode b = blockers.get(k);
            out.println(Fmt.row(indent, k == 0 ? "shadow" : "", (k == 0 ? "BLOCKED by " : "and by ") + ProbeTree.path(roots, b, names)
                    + " at t = " + Fmt.num(b.t()) + ", at " + Fmt.vec(b.worldLocation())));
        }
        if (blockers.size() > MAX_BLOCKERS) {
            out.println(Fmt.row(indent, "", "and " + (blockers.size() - MAX_BLOCKERS) + " more primitives"));
        }
        if (!blockers.isEmpty() && !blockedByGroup) {
            out.println(Fmt.row(indent, "!", "but the scene's group (Group.intersect) finds no blocker, so the renderer lights"
                    + " this point anyway: is Group.intersect still the stub? See TODO(Task 4)"));
        } else if (blockers.isEmpty() && blockedByGroup) {
            out.println(Fmt.row(indent, "!", "but the scene's group (Group.intersect) reports a blocker that no surface"
                    + " reports on its own: the group's loop must return only its children's hits"));
        }
        return blockedByGroup;
    }
}
