package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.SearchCounter;
import ray.math.Bounds;

/** A renderer thread's copy of a primitive (or of any surface not known to be made of parts): one intersection test per search. */
final class CountedSurface extends Surface {
    private final Surface primitive;
    private final SearchCounter counter;

    CountedSurface(Surface primitive, SearchCounter counter) {
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
