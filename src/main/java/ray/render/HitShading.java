package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** How a ray tracer has a hit shaded: by the hit surface's shader, with the renderer's lights, shadow and mirror rays, and counters. */
public interface HitShading {
    /** The radiance that leaves {@code hit} back along {@code ray}, a ray of recursion depth {@code depth}. */
    Vec3 shade(IntersectionRecord hit, Ray ray, int depth);
}
