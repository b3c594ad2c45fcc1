package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: a ray that hits nothing brings back black, not the background color. */
public class RayTracer extends SceneTracer {
    public RayTracer() {
    }

    @Override
    public Vec3 shadeRay(Ray ray, int depth) {
        if (depth >= maxDepth()) {
            return Vec3.ZERO;
        }
        IntersectionRecord hit = new IntersectionRecord();
        if (!surfaces().intersect(hit, ray)) {
            return new Vec3(0, 0, 0);
        }
        return shade(hit, ray, depth);
    }
}
