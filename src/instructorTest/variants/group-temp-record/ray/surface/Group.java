package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** Ray Tracing in One Weekend's hittable_list: a temporary record, its fields copied into out on each closer hit. */
public class Group extends GroupSurface {
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
