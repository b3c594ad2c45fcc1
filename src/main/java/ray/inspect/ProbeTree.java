package ray.inspect;

import java.util.ArrayList;
import java.util.List;
import ray.Ray;
import ray.math.Affine;
import ray.shading.Effect;
import ray.surface.Surface;

/** Tests a ray against every primitive of a surface tree, one by one, and keeps the results as a tree. */
final class ProbeTree {
    private ProbeTree() {
    }

    /** The nodes of {@code root}'s surfaces (the scene's top-level surfaces when root is the scene's group). */
    static List<ProbeNode> of(Surface root, Ray ray) {
        List<ProbeNode> nodes = new ArrayList<>();
        List<Surface> surfaces = root.children();
        for (int k = 0; k < surfaces.size(); k++) {
            nodes.add(probe(surfaces.get(k), ray, Affine.IDENTITY, k));
        }
        return nodes;
    }

    /** Every primitive of the trees, in scene order. */
    static List<ProbeNode> primitives(List<ProbeNode> nodes) {
        List<ProbeNode> all = new ArrayList<>();
        nodes.forEach(n -> all.addAll(n.primitives()));
        return all;
    }

    /** The primitive hit at the smallest t, the earlier one on a tie (as a group keeps it); null if none. */
    static ProbeNode nearest(List<ProbeNode> primitives) {
        ProbeNode best = null;
        for (ProbeNode p : primitives) {
            if (p.isHit() && (best == null || p.t() < best.t())) {
                best = p;
            }
        }
        return best;
    }

    /** Where a node sits, e.g. "#2 Box (…) › triangle #7" or "#3 Group (2 surfaces) › #1 Sphere …". */
    static String path(List<ProbeNode> roots, ProbeNode target, SurfaceNames names) {
        List<ProbeNode> chain = new ArrayList<>();
        if (!find(roots, target, chain)) {
            return names.of(target.surface);
        }
        StringBuilder s = new StringBuilder();
        for (int k = 0; k < chain.size(); k++) {
            s.append(k == 0 ? "" : " › ").append(step(k > 0 ? chain.get(k - 1).surface : null, chain.get(k), names));
        }
        return s.toString();
    }

    /**
     * One step of a path: "triangle #7 (+y face)" inside a mesh or box, "#3 Sphere …" anywhere else
     * ({@code parent} is null at the top of the scene).
     */
    static String step(Surface parent, ProbeNode node, SurfaceNames names) {
        String part = parent == null ? null : parent.partName(node.surface, node.index);
        return part != null ? part : "#" + (node.index + 1) + " " + names.of(node.surface);
    }

    private static boolean find(List<ProbeNode> nodes, ProbeNode target, List<ProbeNode> chain) {
        for (ProbeNode node : nodes) {
            chain.add(node);
            if (node == target || find(node.children, target, chain)) {
                return true;
            }
            chain.remove(chain.size() - 1);
        }
        return false;
    }

    /** The primitive whose surface is {@code surface} (the one a record names), or null. */
    static ProbeNode bySurface(List<ProbeNode> primitives, Surface surface) {
        for (ProbeNode p : primitives) {
            if (p.surface == surface) {
                return p;
            }
        }
        return null;
    }

    private static ProbeNode probe(Surface surface, Ray ray, Affine toWorld, int index) {
        if (surface.effects().contains(Effect.TRANSFORMS) && surface.children().size() == 1) {
            // A placement is shown as the surface it places, with the ray in that surface's coordinates:
            // the same map and the same arithmetic as Transformed.intersect, so the local t values match.
            Affine placement = surface.childPlacement();
            Affine toLocal = placement.inverse();
            Ray local = new Ray(toLocal.applyToPoint(ray.origin), toLocal.applyToVector(ray.direction), ray.start, ray.end);
            Surface inner = surface.children().get(0);
            ProbeNode node = new ProbeNode(inner, true, local, toWorld.after(placement), index);
            fill(node, inner, local);
            return node;
        }
        ProbeNode node = new ProbeNode(surface, false, ray, toWorld, index);
        fill(node, surface, ray);
        return node;
    }

    private static void fill(ProbeNode node, Surface surface, Ray ray) {
        List<Surface> children = surface.children();
        if (children.isEmpty()) {
            node.test = PrimitiveProbe.run(surface, ray);
            return;
        }
        for (int k = 0; k < children.size(); k++) {
            node.children.add(probe(children.get(k), ray, node.toWorld, k));
        }
    }
}
