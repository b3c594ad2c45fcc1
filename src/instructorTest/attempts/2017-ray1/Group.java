package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;

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
        Ray r = new Ray(ray.origin, ray.direction);
        r.start = 1e-3;
        r.end = Double.POSITIVE_INFINITY;
        boolean result = false;
        IntersectionRecord tmp = new IntersectionRecord();
        for (Surface s : surfaces) {
            result = s.intersect(tmp, r);
            if (result) {
                r.end = tmp.t;
                out.set(tmp);
            }
        }
        return result;
    }
}
