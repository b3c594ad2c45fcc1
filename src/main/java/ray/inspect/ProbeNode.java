package ray.inspect;

import java.util.ArrayList;
import java.util.List;
import ray.Ray;
import ray.math.Affine;
import ray.math.Vec3;
import ray.surface.Surface;

/**
 * One surface of the scene tree with what a ray did there: a group lists its children, a
 * primitive holds its own {@link PrimitiveProbe}. A transformed group is one node whose children
 * were tested with the ray taken into the group's coordinates, as Transformed.intersect does.
 */
final class ProbeNode {
    /** The surface as it appears in the scene; for a transformed group, the group inside the wrapper. */
    final Surface surface;
    /** Whether the surface sits in a Transformed wrapper (its children see {@link #ray} in local space). */
    final boolean transformed;
    /** The ray in this node's coordinates: the world ray, or the group's local ray when transformed. */
    final Ray ray;
    /** From this node's coordinates to the world's. */
    final Affine toWorld;
    /** Position among its parent's surfaces, from 0. */
    final int index;
    final List<ProbeNode> children = new ArrayList<>();
    /** Only for primitives. */
    PrimitiveProbe test;

    ProbeNode(Surface surface, boolean transformed, Ray ray, Affine toWorld, int index) {
        this.surface = surface;
        this.transformed = transformed;
        this.ray = ray;
        this.toWorld = toWorld;
        this.index = index;
    }

    boolean isPrimitive() {
        return test != null;
    }

    boolean isHit() {
        return test != null && test.hit;
    }

    double t() {
        return test.record.t;
    }

    /** The hit point in world coordinates. */
    Vec3 worldLocation() {
        return test.record.location == null ? null : toWorld.applyToPoint(test.record.location);
    }

    /** The hit normal in world coordinates, by the inverse transpose as Transformed maps it. */
    Vec3 worldNormal() {
        Vec3 n = test.record.normal;
        return n == null || toWorld.isIdentity() ? n : toWorld.inverse().applyTransposeToVector(n).normalized();
    }

    /** Every primitive below this node (itself, if it is one), in scene order. */
    List<ProbeNode> primitives() {
        List<ProbeNode> all = new ArrayList<>();
        collect(all);
        return all;
    }

    private void collect(List<ProbeNode> into) {
        if (isPrimitive()) {
            into.add(this);
        }
        for (ProbeNode child : children) {
            child.collect(into);
        }
    }
}
