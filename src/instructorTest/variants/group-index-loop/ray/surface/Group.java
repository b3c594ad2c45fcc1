package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;

/** An index loop that builds a new, shorter ray for each child from the closest t so far. */
public class Group extends GroupSurface {
    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        double closest = ray.end;
        boolean hit = false;
        for (int i = 0; i < surfaces.size(); i++) {
            Ray segment = new Ray(ray.origin, ray.direction, ray.start, closest);
            if (surfaces.get(i).intersect(out, segment)) {
                closest = out.t;
                hit = true;
            }
        }
        return hit;
    }
}
