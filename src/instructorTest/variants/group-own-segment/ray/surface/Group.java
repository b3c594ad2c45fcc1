package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** Known wrong: searches its own segment (1e-3, ∞) instead of the caller's, so a shadow ray is blocked beyond the light and a ray starting at 0 misses what lies within 1e-3. */
public class Group extends GroupSurface {
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Ray closestSoFar = new Ray(ray.origin, ray.direction, 1e-3, Double.POSITIVE_INFINITY);
        boolean hitAny = false;
        for (Surface surface : surfaces) {
            if (surface.intersect(out, closestSoFar)) {
                closestSoFar.end = out.t;
                hitAny = true;
            }
        }
        return hitAny;
    }
}
