package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** A fresh record per child, the best one kept, and out.set(best) at the end. */
public class Group extends GroupSurface {
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        IntersectionRecord best = null;
        Ray shortened = ray.copy();
        for (Surface surface : surfaces) {
            IntersectionRecord record = new IntersectionRecord();
            if (surface.intersect(record, shortened)) {
                best = record;
                shortened.end = record.t;
            }
        }
        if (best == null) {
            return false;
        }
        out.set(best);
        return true;
    }
}
