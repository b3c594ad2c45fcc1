package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** Known wrong: keeps the closest hit, but returns whether the last child it tried was hit, not whether any was. */
public class Group extends GroupSurface {
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        Ray closestSoFar = ray.copy();
        boolean hit = false;
        for (Surface surface : surfaces) {
            hit = surface.intersect(out, closestSoFar);
            if (hit) {
                closestSoFar.end = out.t;
            }
        }
        return hit;
    }
}
