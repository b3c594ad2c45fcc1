package ray.accel;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Bounds;

/**
 * What a hierarchy can hold: something with a box that a ray can hit. Every surface is one; the
 * hierarchy needs nothing more of it, so this package knows no surface type.
 */
public interface Hittable {
    /** Fills {@code out} with the hit for some t in (ray.start, ray.end), if any, and says whether there is one. */
    boolean intersect(IntersectionRecord out, Ray ray);

    /** Whether the ray hits it anywhere in (ray.start, ray.end). */
    boolean intersectsAny(Ray ray);

    /** A box that holds every point where it can be hit. */
    Bounds bounds();
}
