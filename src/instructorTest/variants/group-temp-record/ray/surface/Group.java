package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;

/** Ray Tracing in One Weekend's hittable_list: a temporary record, its fields copied into out on each closer hit. */
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
        IntersectionRecord temp = new IntersectionRecord();
        boolean hitAnything = false;
        double closestSoFar = ray.end;
        for (Surface surface : surfaces) {
            if (surface.intersect(temp, new Ray(ray.origin, ray.direction, ray.start, closestSoFar))) {
                hitAnything = true;
                closestSoFar = temp.t;
                out.t = temp.t;
                out.location = temp.location;
                out.normal = temp.normal;
                out.surface = temp.surface;
                out.beta = temp.beta;
                out.gamma = temp.gamma;
                out.texU = temp.texU;
                out.texV = temp.texV;
            }
        }
        return hitAnything;
    }
}
