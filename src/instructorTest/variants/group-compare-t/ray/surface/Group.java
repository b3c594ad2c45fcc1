package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** No shortened ray: every child is tested on the whole segment and the smallest t kept (ties keep the first). */
public class Group extends GroupSurface {
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        IntersectionRecord closest = null;
        for (Surface surface : surfaces) {
            IntersectionRecord candidate = new IntersectionRecord();
            if (surface.intersect(candidate, ray) && (closest == null || candidate.t < closest.t)) {
                closest = candidate;
            }
        }
        if (closest != null) {
            out.set(closest);
        }
        return closest != null;
    }
}
