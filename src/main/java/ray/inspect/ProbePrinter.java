package ray.inspect;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import ray.surface.Surface;
import ray.surface.SurfaceKind;

/**
 * Prints a {@link ProbeTree} as an indented list, one line per surface: groups with their
 * children below them, primitives with their t and hit point or "miss". The triangles of a mesh
 * or a box (and of any group of more than {@value #SUMMARIZE_OVER} primitives) are summed up in
 * one line unless every triangle is asked for.
 */
final class ProbePrinter {
    static final int SUMMARIZE_OVER = 20;
    private static final int MAX_LABEL = 72;

    private final SurfaceNames names;
    private final boolean all;
    private final ProbeNode nearest;
    /** Pairs of (indent + label, result), printed with the results in one column. */
    private final List<String[]> rows = new ArrayList<>();

    ProbePrinter(SurfaceNames names, boolean all, ProbeNode nearest) {
        this.names = names;
        this.all = all;
        this.nearest = nearest;
    }

    void print(List<ProbeNode> nodes, String indent, PrintWriter out) {
        for (ProbeNode node : nodes) {
            add(node, indent);
        }
        int width = 0;
        for (String[] row : rows) {
            if (!row[1].isEmpty()) {
                width = Math.max(width, Math.min(MAX_LABEL, row[0].length()));
            }
        }
        for (String[] row : rows) {
            out.println(row[1].isEmpty() ? row[0] : String.format(Locale.ROOT, "%-" + width + "s  %s", row[0], row[1]));
        }
    }

    private void add(ProbeNode node, String indent) {
        String label = indent + "#" + (node.index + 1) + " " + names.of(node.surface);
        if (node.isPrimitive()) {
            rows.add(new String[] {label, result(node)});
            details(node.test, indent + "     ");
            return;
        }
        if (node.transformed) {
            rows.add(new String[] {label + ", transformed:", ""});
            rows.add(new String[] {indent + "   children tested in its own coordinates, where the ray is "
                    + Fmt.ray(node.ray), ""});
        } else if (!summarized(node)) {
            rows.add(new String[] {label, ""});
        }
        if (summarized(node)) {
            if (!node.transformed) {
                rows.add(new String[] {label, summary(node, nearest)});
            } else {
                rows.add(new String[] {indent + "   its triangles:", summary(node, nearest)});
            }
            triangleDetails(node, indent + "     ");
            return;
        }
        for (ProbeNode child : node.children) {
            add(child, indent + "   ");
        }
    }

    /** Why a miss within rounding of an edge is no mistake. */
    static final String CRACK = "a test may round such a ray to either side, so where two triangles share the edge both may"
            + " miss it, a crack pixel the render tests allow";

    /** Whether the node's primitives are summed up in one line (a mesh, a box, a large group of primitives). */
    boolean summarized(ProbeNode node) {
        if (all || node.children.isEmpty() || !node.children.stream().allMatch(ProbeNode::isPrimitive)) {
            return false;
        }
        // A mesh's or a box's triangles (parts the surface names itself) are summarized, as are many primitives.
        return node.surface.partName(null, 0) != null || node.children.size() > SUMMARIZE_OVER;
    }

    private String result(ProbeNode p) {
        if (p.test.failure != null) {
            return "threw " + p.test.failure;
        }
        if (!p.test.hit) {
            String edge = EdgeGraze.ofMiss(p);
            return edge == null ? "miss" : "miss   (the ray passes within rounding of its edge " + edge + ": " + CRACK + ")";
        }
        return "hit  t = " + Fmt.num(p.t()) + "  at " + Fmt.vec(p.worldLocation()) + (p == nearest ? "  ← nearest" : "");
    }

    /**
     * "12 triangles: 2 hit (nearest t = … at triangle #3, at (…)), 10 miss": a group of primitives in
     * one line ("1 primitive: …" when they are not all triangles).
     */
    static String summary(ProbeNode group, ProbeNode nearest) {
        int hits = 0;
        int failures = 0;
        ProbeNode best = null;
        for (ProbeNode c : group.children) {
            if (c.test.failure != null) {
                failures++;
            } else if (c.isHit()) {
                hits++;
                if (best == null || c.t() < best.t()) {
                    best = c;
                }
            }
        }
        int n = group.children.size();
        // A mesh's or box's parts are triangles; a group's may be anything.
        boolean triangles = group.children.stream().allMatch(c -> c.surface.kind() == SurfaceKind.TRIANGLE);
        StringBuilder s = new StringBuilder(Fmt.count(n, triangles ? "triangle" : "primitive")).append(": ").append(hits).append(" hit");
        if (best != null) {
            s.append(" (nearest t = ").append(Fmt.num(best.t())).append(" at ").append(partName(group.surface, best))
                    .append(", at ").append(Fmt.vec(best.worldLocation())).append(best == nearest ? "  ← nearest" : "")
                    .append(")");
        }
        s.append(", ").append(n - hits - failures).append(" miss");
        long grazed = group.children.stream().filter(c -> EdgeGraze.ofMiss(c) != null).count();
        if (grazed > 0) {
            s.append(" (").append(grazed == 1 ? "one" : grazed + " of them").append(" within rounding of an edge: ").append(CRACK).append(")");
        }
        if (failures > 0) {
            s.append(", ").append(failures).append(" threw");
        }
        return s.toString();
    }

    /** A primitive's broken contract, one line each under it. */
    private void details(PrimitiveProbe test, String indent) {
        for (String problem : test.problems) {
            rows.add(new String[] {indent + "! " + problem, ""});
        }
    }

    /** The first few failures and broken contracts of a summarized group's triangles. */
    private void triangleDetails(ProbeNode group, String indent) {
        List<String> lines = new ArrayList<>();
        for (ProbeNode c : group.children) {
            String which = indent + "! triangle #" + (c.index + 1) + ": ";
            if (c.test.failure != null) {
                lines.add(which + "threw " + c.test.failure);
            }
            c.test.problems.forEach(problem -> lines.add(which + problem));
        }
        int shown = Math.min(lines.size(), 3);
        lines.subList(0, shown).forEach(line -> rows.add(new String[] {line, ""}));
        if (lines.size() > shown) {
            rows.add(new String[] {indent + "! … and " + (lines.size() - shown) + " more like these (--all lists every triangle)", ""});
        }
    }

    /** "triangle #8 (+y face)" as the summarized surface names its part, else "#8". */
    private static String partName(Surface whole, ProbeNode part) {
        String name = whole.partName(part.surface, part.index);
        return name != null ? name : "#" + (part.index + 1);
    }
}
