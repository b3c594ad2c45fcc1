package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;

/** A fresh record per child, the best one kept, and out.set(best) at the end. */
public class Group extends Surface {
    private final List<Surface> surfaces = new ArrayList<>();

    public void addSurface(Surface surface) {
        surfaces.add(surface);
    }

    @Override
    public List<Surface> children() {
        return Collections.unmodifiableList(surfaces);
    }

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
