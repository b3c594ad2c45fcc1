package ray.hidden;

import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.shading.Light;
import ray.shading.ShadingContext;

/**
 * A hidden shading case built by hand: a point, its unit normal, the ray from the eye that found it,
 * the scene's lights and which of them something blocks. Its context answers each shadow test from
 * that list (by the light's position) and each mirror ray with {@link #mirror}, black unless a case
 * says otherwise.
 *
 * @param <C> the case's own class, which {@link #light} returns for chaining
 */
abstract class HiddenLitPoint<C extends HiddenLitPoint<C>> {
    final IntersectionRecord hit = new IntersectionRecord();
    final Ray ray;
    final List<Light> lights = new ArrayList<>();
    final List<Boolean> blocked = new ArrayList<>();

    /** The point {@code location} with normal {@code normal} (made unit length), seen from {@code eye}. */
    HiddenLitPoint(Vec3 location, Vec3 normal, Vec3 eye) {
        hit.location = location;
        hit.normal = normal.normalized();
        hit.t = 1;
        ray = new Ray(eye, location.minus(eye));
    }

    /** This case, as its own class. */
    protected abstract C self();

    C light(Vec3 position, Vec3 intensity, boolean isBlocked) {
        lights.add(new Light(position, intensity));
        blocked.add(isBlocked);
        return self();
    }

    /** What a mirror ray from {@code at} along {@code direction} brings back: black here. */
    protected Vec3 mirror(IntersectionRecord at, Vec3 direction, int depth) {
        return Vec3.ZERO;
    }

    ShadingContext context() {
        return new ShadingContext() {
            @Override
            public List<Light> lights() {
                return lights;
            }

            @Override
            public boolean unoccluded(IntersectionRecord at, Vec3 position) {
                for (int k = 0; k < lights.size(); k++) {
                    if (lights.get(k).getPosition().equals(position)) {
                        return !blocked.get(k);
                    }
                }
                return true;
            }

            @Override
            public Vec3 radiance(IntersectionRecord at, Vec3 direction, int depth) {
                return mirror(at, direction, depth);
            }
        };
    }

    /** The case in words, for messages: "the point … with normal … seen from …, lit by …". */
    String describe() {
        StringBuilder s = new StringBuilder("the point " + hit.location + " with normal " + hit.normal + " seen from " + ray.origin);
        for (int k = 0; k < lights.size(); k++) {
            s.append(k == 0 ? ", lit by " : "; ").append("a light at ").append(lights.get(k).getPosition()).append(" of intensity ")
                    .append(lights.get(k).getIntensity()).append(blocked.get(k) ? " (blocked)" : "");
        }
        return s.toString();
    }
}
