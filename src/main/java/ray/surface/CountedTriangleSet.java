package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.math.Bounds;

/** A renderer thread's copy of a box or mesh, searched through its hierarchy or by the plain loop, counting both kinds of test. */
final class CountedTriangleSet extends Surface {
    private final TriangleSet set;
    private final boolean accelerated;
    private final SearchCounter counter;

    CountedTriangleSet(TriangleSet set, Acceleration acceleration, SearchCounter counter) {
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
