package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;

/** Known wrong: returns the first child that is hit, not the closest. */
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
        for (Surface surface : surfaces) {
            if (surface.intersect(out, ray)) {
                return true;
            }
        }
        return false;
    }
}
