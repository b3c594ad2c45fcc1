package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;

/** Known wrong: keeps the closest hit, but returns whether the last child it tried was hit, not whether any was. */
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
