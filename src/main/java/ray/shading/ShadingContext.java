package ray.shading;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** What a shader may ask of the renderer: the lights, shadow tests and the radiance along new rays. */
public interface ShadingContext {
    List<Light> lights();

    /** Whether nothing blocks the segment from the hit point to {@code lightPosition} (traces one shadow ray). */
    boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition);

    /**
     * The radiance arriving at the hit from direction {@code direction} (traces one reflection ray,
     * which starts just off the surface on the side it leaves to).
     *
     * @param depth the new ray's recursion depth (camera rays have depth 0)
     */
    Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth);
}
