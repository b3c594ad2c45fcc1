package ray.shading;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A stand-in for the renderer that lets shader tests control shadows and reflected radiance
 * and count what the shader asks for.
 */
final class FakeShadingContext implements ShadingContext {
    final List<Light> lights = new ArrayList<>();
    /** Which light positions are visible from the hit; everything is lit unless a test says otherwise. */
    Predicate<Vec3> lit = position -> true;
    /** What every reflection ray "sees". */
    Vec3 reflected = Vec3.ZERO;

    int shadowRays;
    final List<Vec3> reflectionDirections = new ArrayList<>();
    final List<Integer> reflectionDepths = new ArrayList<>();

    FakeShadingContext light(Vec3 position, Vec3 intensity) {
        lights.add(new Light(position, intensity));
        return this;
    }

    @Override
    public List<Light> lights() {
        return lights;
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        shadowRays++;
        return lit.test(lightPosition);
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        reflectionDirections.add(direction);
        reflectionDepths.add(depth);
        return reflected;
    }

    /** A hit at {@code location} with unit normal {@code normal}, as a surface would report it. */
    static IntersectionRecord hit(Vec3 location, Vec3 normal) {
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 1;
        hit.location = location;
        hit.normal = normal;
        return hit;
    }

    /** A ray arriving at {@code target} from {@code eye}, with a deliberately non-unit direction. */
    static Ray rayFrom(Vec3 eye, Vec3 target) {
        return new Ray(eye, target.minus(eye).times(3));
    }
}
