package ray.inspect;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.assignment.Assignment;
import ray.math.Vec3;
import ray.scene.Scene;

/**
 * The shadow ray from a hit to one light, tested the two ways the camera ray is: against every
 * primitive alone (to name the blockers) and by the scene's group (what the renderer uses).
 */
final class ShadowCheck {
    private static final int MAX_BLOCKERS = 3;

    /** The renderer's shadow ray (from {@code recorded}). */
    final Ray ray;
    /** The shadow ray's probe of every surface, for naming blockers by their place in the scene. */
    final List<ProbeNode> roots;
    /** The primitives that report a hit on the shadow ray alone, nearest first. */
    final List<ProbeNode> blockers;
    /** Whether the scene's group reports a blocker: what the renderer goes by. */
    final boolean blockedByGroup;
    /** What the scene's group threw, in one line, or null. */
    final String groupFailure;

    private ShadowCheck(Ray ray, List<ProbeNode> roots, List<ProbeNode> blockers, boolean blockedByGroup, String groupFailure) {
        this.ray = ray;
        this.roots = roots;
        this.blockers = blockers;
        this.blockedByGroup = blockedByGroup;
        this.groupFailure = groupFailure;
    }

    /** Traces the shadow ray from {@code hit} toward the light both ways. */
    static ShadowCheck of(Scene scene, RecordedShading recorded, IntersectionRecord hit, Vec3 lightPosition) {
        Ray shadowRay = recorded.shadowRay(hit, lightPosition);
        List<ProbeNode> roots = ProbeTree.of(scene.getSurfaces(), shadowRay);
        List<ProbeNode> blockers = new ArrayList<>();
        for (ProbeNode p : ProbeTree.primitives(roots)) {
            if (p.isHit()) {
                blockers.add(p);
            }
        }
        // Nearest blocker first: the one a student would see standing between the point and the light.
        blockers.sort((a, b) -> Double.compare(a.t(), b.t()));
        try {
            boolean blocked = scene.getSurfaces().intersect(new IntersectionRecord(), shadowRay.copy());
            return new ShadowCheck(shadowRay, roots, blockers, blocked, null);
        } catch (RuntimeException | StackOverflowError e) {
            return new ShadowCheck(shadowRay, roots, blockers, false, Failure.oneLine(e));
        }
    }

    /** The nearest primitive that blocks the shadow ray alone, or null. */
    ProbeNode nearestBlocker() {
        return blockers.isEmpty() ? null : blockers.get(0);
    }

    /**
     * What is wrong between the group's answer and the surfaces' own, in one line, or null: the
     * surfaces see a blocker the group does not (a stub group), or the other way round.
     */
    String disagreement() {
        if (!blockers.isEmpty() && !blockedByGroup) {
            return "but the scene's group (Group.intersect) finds no blocker, so the renderer lights"
                    + " this point anyway: is Group.intersect still the stub? See " + Assignment.current().todo("group");
        }
        if (blockers.isEmpty() && blockedByGroup) {
            return "but the scene's group (Group.intersect) reports a blocker that no surface"
                    + " reports on its own: the group's loop must return only its children's hits";
        }
        return null;
    }

    /** What went wrong with the shadow ray, in one line, or null: the group threw, or it disagrees with the surfaces ({@link #disagreement}). */
    String problem() {
        return groupFailure != null ? "the scene's group threw " + groupFailure : disagreement();
    }

    /** Prints the shadow ray and what blocks it; returns whether the renderer sees the light as blocked. */
    boolean print(SurfaceNames names, String indent, PrintWriter out) {
        out.println(Fmt.row(indent, "shadow ray", "from " + Fmt.vec(ray.origin) + " (just off the surface) along "
                + Fmt.vec(ray.direction) + ", t in (0, 1 − 1e-9)"));
        if (groupFailure != null) {
            out.println(Fmt.row(indent, "shadow", problem()));
            return false;
        }
        if (blockers.isEmpty()) {
            out.println(Fmt.row(indent, "shadow", "not blocked: every surface misses the shadow ray"));
        }
        for (int k = 0; k < Math.min(MAX_BLOCKERS, blockers.size()); k++) {
            ProbeNode b = blockers.get(k);
            out.println(Fmt.row(indent, k == 0 ? "shadow" : "", (k == 0 ? "BLOCKED by " : "and by ") + ProbeTree.path(roots, b, names)
                    + " at t = " + Fmt.num(b.t()) + ", at " + Fmt.vec(b.worldLocation())));
            // A blocker behind the shadow ray's start (a surface that ignores ray.start) darkens the point wrongly.
            String outside = RecordChecks.outsideSegment(b.t(), ray, "shadow ray");
            if (outside != null) {
                out.println(Fmt.row(indent, "!", outside));
            }
        }
        if (blockers.size() > MAX_BLOCKERS) {
            out.println(Fmt.row(indent, "", "and " + (blockers.size() - MAX_BLOCKERS) + " more primitives"));
        }
        String disagreement = disagreement();
        if (disagreement != null) {
            out.println(Fmt.row(indent, "!", disagreement));
        }
        return blockedByGroup;
    }
}
