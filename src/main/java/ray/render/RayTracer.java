package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The color a ray brings back: its closest hit shaded, or the background. Its scene is kept by SceneTracer. */
public class RayTracer extends SceneTracer {

    public RayTracer() {
    }

    @Override
    public Vec3 shadeRay(Ray ray, int depth) {
        // TODO(Task 8): return the light that arrives along the ray.
        //   Return the light that comes back along the ray: what its closest hit in the scene sends back,
        //   or the scene's background color when the ray hits nothing.
        //   Conventions (the reference images depend on them):
        //   - surfaces() is the whole scene as one surface: its intersect finds the closest hit within the
        //     ray's own segment (the ray comes ready: do not change its start or end).
        //   - shade(hit, ray, depth) has the hit surface's shader shade a hit (its lights, shadows and
        //     mirror rays, which come back here with depth + 1); pass the depth on as it is.
        //   - backgroundColor() is the color of a ray that hits nothing.
        //   - The course limits paths of mirror rays: a ray whose depth is maxDepth() or more brings back black,
        //     and is not traced at all.
        // HINTS steps
        //   1) If the ray is at or past the depth limit, return black.
        //   2) Make a new intersection record and ask the scene's surfaces for the ray's closest hit.
        //   3) If there is none, return the background color.
        //   4) Otherwise return the shaded hit, at the same depth.
        // HINTS formulas
        //   1) If depth >= maxDepth(), return Vec3.ZERO.
        //   2) IntersectionRecord hit = new IntersectionRecord(); boolean found = surfaces().intersect(hit, ray).
        //   3) If !found, return backgroundColor().
        //   4) Else return shade(hit, ray, depth).
        // END HINTS
        // BEGIN SOLUTION
        if (depth >= maxDepth()) {
            return Vec3.ZERO; // past the course's limit on a path: black, untraced
        }
        IntersectionRecord hit = new IntersectionRecord();
        if (!surfaces().intersect(hit, ray)) {
            return backgroundColor();
        }
        return shade(hit, ray, depth);
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
