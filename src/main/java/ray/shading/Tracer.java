package ray.shading;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** What a shader may ask of the renderer: the lights, shadow tests and the radiance along new rays. */
public interface Tracer {
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

    /**
     * Told once per light for which a shader evaluates a specular term (Phong's highlight), so a
     * renderer can count that work. The default counts nothing.
     */
    default void specularEvaluated() {
    }

    /**
     * Whether shaders may skip work that cannot change the pixel: a shadow ray for a light whose
     * unshadowed contribution is zero, a reflection ray whose reflectance is zero. True for every
     * real render; a tracer that answers false makes them do all the work, so a test can check
     * that skipping leaves the image bit for bit the same.
     */
    default boolean skipsZeroWork() {
        return true;
    }
}
