package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: the hit is shaded one depth deeper than its ray (the shader adds the next level itself). */
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
            return backgroundColor();
        }
        return shade(hit, ray, depth + 1);
    }
}
