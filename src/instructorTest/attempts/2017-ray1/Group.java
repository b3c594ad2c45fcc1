package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

public class Group extends GroupSurface {
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
