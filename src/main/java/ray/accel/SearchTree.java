package ray.accel;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Bounds;
import ray.surface.Group;
import ray.surface.Surface;
import ray.surface.Transformed;
import ray.surface.TriangleSet;

/**
 * A renderer thread's view of the scene's surfaces: the same tree, rebuilt around the same
 * primitives so that every search is counted where it happens ({@link SearchCounter}) and runs as
 * the chosen {@link Acceleration} says. Groups are copied as groups (so the student's loop is what
 * searches them), placements as placements, and each primitive is wrapped by a counter of its
 * tests; a hit still names the scene's own primitive, since the primitive fills the record.
 */
public final class SearchTree {
    private SearchTree() {
    }

    /** The counting copy of {@code surface} and everything under it. */
    public static Surface of(Surface surface, Acceleration acceleration, SearchCounter counter) {
        if (surface instanceof TriangleSet) {
            return new CountedSet((TriangleSet) surface, acceleration, counter);
        }
        if (surface instanceof Transformed) {
            Transformed placed = (Transformed) surface;
            return placed.placing(of(placed.placed(), acceleration, counter), acceleration == Acceleration.BVH, counter);
        }
        if (surface.getClass() == Group.class) {
            SearchGroup copy = new SearchGroup();
            copy.setShader(surface.getShader());
            for (Surface child : surface.children()) {
                copy.addSurface(of(child, acceleration, counter));
            }
            return copy.completed();
        }
        return new CountedPrimitive(surface, counter);
    }

    /**
     * A group's copy: the student's {@link Group} loop finds its closest hit; shadow rays ask its
     * parts in turn from an array, stopping at the first that is hit.
     */
    private static final class SearchGroup extends Group {
        private Surface[] parts;

        SearchGroup completed() {
            parts = children().toArray(new Surface[0]);
            return this;
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            for (Surface part : parts) {
                if (part.intersectsAny(ray)) {
                    return true;
                }
            }
            return false;
        }
    }

    /** A primitive (or any surface not known to be made of parts): one intersection test per search. */
    private static final class CountedPrimitive extends Surface {
        private final Surface primitive;
        private final SearchCounter counter;

        CountedPrimitive(Surface primitive, SearchCounter counter) {
            this.primitive = primitive;
            this.counter = counter;
            setShader(primitive.getShader());
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            counter.count(1, 0);
            return primitive.intersect(out, ray);
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            counter.count(1, 0);
            return primitive.intersectsAny(ray);
        }

        @Override
        public Bounds bounds() {
            return primitive.bounds();
        }

        @Override
        public List<Surface> children() {
            return List.of(primitive);
        }

        @Override
        public String toString() {
            return primitive.toString();
        }
    }

    /** A box or mesh, searched through its hierarchy or by the plain loop, counting both kinds of test. */
    private static final class CountedSet extends Surface {
        private final TriangleSet set;
        private final boolean accelerated;
        private final SearchCounter counter;

        CountedSet(TriangleSet set, Acceleration acceleration, SearchCounter counter) {
            this.set = set;
            this.accelerated = acceleration == Acceleration.BVH;
            this.counter = counter;
            setShader(set.getShader());
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            return accelerated ? set.closestHit(out, ray, counter) : set.closestHitLinear(out, ray, counter);
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            return accelerated ? set.anyHit(ray, counter) : set.closestHitLinear(new IntersectionRecord(), ray, counter);
        }

        @Override
        public Bounds bounds() {
            return set.bounds();
        }

        @Override
        public List<Surface> children() {
            return List.of(set);
        }

        @Override
        public String toString() {
            return set.toString();
        }
    }
}
