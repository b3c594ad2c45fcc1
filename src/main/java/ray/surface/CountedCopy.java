package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.bvh.StudentBvh;
import ray.math.Bounds;

/**
 * A renderer thread's copy of a surface ({@link Surface#searchCopy}) that counts the tests of each
 * search into the thread's counter. It is where the original is, shades as it does, and a hit still
 * names the original's primitive, since the primitive fills the record.
 */
abstract class CountedCopy<S extends Surface> extends Surface {
    final S original;
    final SearchCounter counter;

    CountedCopy(S original, SearchCounter counter) {
        this.original = original;
        this.counter = counter;
        setShader(original.getShader());
    }

    @Override
    public Bounds bounds() {
        return original.bounds();
    }

    @Override
    public List<Surface> children() {
        return List.of(original);
    }

    @Override
    public String toString() {
        return original.toString();
    }

    /** A primitive (or any surface not known to be made of parts): one intersection test per search. */
    static final class OneTest extends CountedCopy<Surface> {
        OneTest(Surface primitive, SearchCounter counter) {
            super(primitive, counter);
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            counter.count(1, 0);
            return original.intersect(out, ray);
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            counter.count(1, 0);
            return original.intersectsAny(ray);
        }
    }

    /** A box or mesh, searched through its hierarchy or by the plain loop, counting both kinds of test. */
    static final class OfTriangles extends CountedCopy<TriangleSet> {
        private final boolean accelerated;
        /** The students' tree, searched by this thread, under {@link Acceleration#STUDENT} (for a set with a tree). */
        private final StudentBvh.Search studentSearch;

        OfTriangles(TriangleSet set, Acceleration acceleration, SearchCounter counter) {
            super(set, counter);
            this.accelerated = acceleration.accelerated();
            this.studentSearch = acceleration == Acceleration.STUDENT && set.hasTree() ? set.studentTree().search() : null;
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            if (studentSearch != null) {
                return studentSearch.closestHit(out, ray, counter);
            }
            return accelerated ? original.closestHit(out, ray, counter) : original.closestHitLinear(out, ray, counter);
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            if (studentSearch != null) {
                return studentSearch.anyHit(ray, counter);
            }
            return accelerated ? original.anyHit(ray, counter) : original.closestHitLinear(new IntersectionRecord(), ray, counter);
        }
    }
}
