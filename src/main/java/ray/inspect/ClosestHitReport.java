package ray.inspect;

import java.io.PrintWriter;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.assignment.Assignment;
import ray.math.Vec3;
import ray.scene.Scene;

/**
 * The hit the renderer shades: the closest one as the scene's group reports it. Checked against
 * the smallest t of the surfaces tested one by one, because a group loop that keeps the last hit
 * instead of the closest, or a stub that reports none, is exactly where they differ.
 */
final class ClosestHitReport {
    private final Scene scene;
    private final SurfaceNames names;
    private final PrintWriter out;

    ClosestHitReport(Scene scene, SurfaceNames names, PrintWriter out) {
        this.scene = scene;
        this.names = names;
        this.out = out;
    }

    /** Prints the closest hit and its shading; returns the camera ray's radiance, or null if it could not be computed. */
    Vec3 explain(Ray ray, List<ProbeNode> roots, ProbeNode nearest) {
        out.println("Closest hit, as the scene's group reports it (scene.getSurfaces().intersect, i.e. Group.intersect):");
        IntersectionRecord hit = new IntersectionRecord();
        boolean found;
        try {
            found = scene.getSurfaces().intersect(hit, ray.copy());
        } catch (RuntimeException | StackOverflowError e) {
            out.println("  ! it threw " + Failure.oneLine(e));
            out.println();
            return null;
        }
        if (!found) {
            out.println("  none: the pixel shows the background color " + Fmt.vec(scene.getBackColor()));
            if (nearest != null) {
                out.println("  ! but " + hitAlone(roots, nearest, names));
            }
            out.println();
            return scene.getBackColor();
        }
        out.println(Fmt.row("  ", "surface", surfacePath(hit, roots, names)));
        out.println(Fmt.row("  ", "t", Fmt.num(hit.t)));
        out.println(Fmt.row("  ", "location", Fmt.vec(hit.location)));
        out.println(Fmt.row("  ", "normal", Fmt.vec(hit.normal)));
        RecordChecks.of(hit, ray).forEach(this::flag);
        out.println(Fmt.row("  ", "shader", hit.surface == null ? "none (the record names no surface)"
                : ShadingReport.describe(hit.surface.getShader())));
        consistency(hit, roots, nearest);
        out.println();
        String lacks = lacks(hit);
        if (lacks != null) {
            out.println("The hit cannot be shaded: its record lacks " + lacks);
            out.println();
            return null;
        }
        out.println("Shading at the hit:");
        try {
            Vec3 radiance = new ShadingReport(scene, names, new RecordedShading(scene), out).explain(hit.surface.getShader(), hit, ray, "  ");
            out.println();
            return radiance;
        } catch (RuntimeException | StackOverflowError e) {
            out.println("  ! shading threw " + Failure.oneLine(e));
            out.println();
            return null;
        }
    }

    /** A "!" line under the row it is about, when there is something to say. */
    private void flag(String problem) {
        if (problem != null) {
            out.println(Fmt.row("  ", "!", problem));
        }
    }

    /** Where the group's hit is in the scene ("#1 Box (…) › triangle #8 (+y face)"), or its surface as the record names it. */
    static String surfacePath(IntersectionRecord hit, List<ProbeNode> roots, SurfaceNames names) {
        ProbeNode winner = ProbeTree.bySurface(ProbeTree.primitives(roots), hit.surface);
        return winner != null ? ProbeTree.path(roots, winner, names) : String.valueOf(hit.surface);
    }

    /** What the group missed: "#1 Sphere … is hit at t = 4 when tested alone: is Group.intersect still the stub? …". */
    static String hitAlone(List<ProbeNode> roots, ProbeNode nearest, SurfaceNames names) {
        return ProbeTree.path(roots, nearest, names) + " is hit at t = " + Fmt.num(nearest.t())
                + " when tested alone: is Group.intersect still the stub? See " + Assignment.current().todo("group");
    }

    /** What a hit's record lacks for shading ("the surface", "a shader", "the normal", "the location"), or null when it can be shaded. */
    static String lacks(IntersectionRecord hit) {
        return hit.surface == null ? "the surface" : hit.surface.getShader() == null ? "a shader"
                : hit.normal == null ? "the normal" : hit.location == null ? "the location" : null;
    }

    private void consistency(IntersectionRecord hit, List<ProbeNode> roots, ProbeNode nearest) {
        out.println("  " + check(hit, roots, nearest, names));
    }

    /**
     * The group's hit checked against the smallest t of the surfaces alone, in one line: "✓ …",
     * "(a tie …)", or "! …" when the group did not return the closest hit: naming the primitive that
     * broke the intersect contract when one did ({@link SegmentEvidence}), else the group.
     */
    static String check(IntersectionRecord hit, List<ProbeNode> roots, ProbeNode nearest, SurfaceNames names) {
        if (nearest == null) {
            return "! no surface reports a hit when tested alone: the group's loop must return only its children's hits";
        }
        double tolerance = 1e-12 * Math.max(1, Math.abs(nearest.t()));
        if (Math.abs(hit.t - nearest.t()) > tolerance) {
            String culprit = SegmentEvidence.culprit(roots, nearest, hit.surface, names);
            if (culprit != null) {
                return culprit;
            }
            return "! the smallest t in the list above is " + Fmt.num(nearest.t()) + ", at " + ProbeTree.path(roots, nearest, names)
                    + ": the group must keep the closest hit (shorten the ray to end at each hit's t). See " + Assignment.current().todo("group");
        }
        if (hit.surface != nearest.surface) {
            return "(a tie at t = " + Fmt.num(hit.t) + " with " + ProbeTree.path(roots, nearest, names) + ")";
        }
        return "✓ the nearest hit in the list above";
    }
}
