package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** Known wrong: returns the first child that is hit, not the closest. */
public class Group extends GroupSurface {
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        for (Surface surface : surfaces) {
            if (surface.intersect(out, ray)) {
                return true;
            }
        }
        return false;
    }
}
