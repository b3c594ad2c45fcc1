package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: unbounded depth: no limit on a path of mirror rays, so two facing mirrors trace without end. */
public class RayTracer extends SceneTracer {

    public RayTracer() {
    }

    @Override
    public Vec3 shadeRay(Ray ray, int depth) {
        IntersectionRecord hit = new IntersectionRecord();
        if (!surfaces().intersect(hit, ray)) {
            return backgroundColor();
        }
        return shade(hit, ray, depth);
    }
}
