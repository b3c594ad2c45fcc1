package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Searches a copy of the ray (so the search cannot change the caller's), and shades the hit seen along the original. */
public class RayTracer extends SceneTracer {
    public RayTracer() {
    }

    @Override
    public Vec3 shadeRay(Ray ray, int depth) {
        if (depth > maxDepth() - 1) {
            return Vec3.ZERO;
        }
        Ray searched = new Ray(ray.origin, ray.direction, ray.start, ray.end);
        IntersectionRecord closest = new IntersectionRecord();
        boolean found = surfaces().intersect(closest, searched);
        if (found) {
            return shade(closest, ray, depth);
        }
        return backgroundColor();
    }
}
