package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** One expression: black past the depth limit, the shaded hit if the search finds one, else the background. */
public class RayTracer extends SceneTracer {
    public RayTracer() {
    }

    @Override
    public Vec3 shadeRay(Ray ray, int depth) {
        IntersectionRecord record = new IntersectionRecord();
        return depth >= maxDepth() ? new Vec3(0, 0, 0) : surfaces().intersect(record, ray) ? shade(record, ray, depth) : backgroundColor();
    }
}
