package ray.render;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Light;
import ray.shading.Tracer;
import ray.surface.Surface;

/** Traces rays through one scene for one thread, counting them. Not shared between threads. */
final class PixelTracer implements Tracer {
    private final Scene scene;
    private final Surface surfaces;
    private final RayStats stats = new RayStats();
    /** Scratch record for shadow tests, whose hit is never read. */
    private final IntersectionRecord shadowHit = new IntersectionRecord();

    PixelTracer(Scene scene) {
        this.scene = scene;
        this.surfaces = scene.getSurfaces();
    }

    RayStats stats() {
        return stats;
    }

    /** The radiance a camera ray sees. */
    Vec3 cameraRadiance(Ray ray) {
        stats.camera++;
        return shade(ray, 0);
    }

    private Vec3 shade(Ray ray, int depth) {
        IntersectionRecord hit = new IntersectionRecord();
        if (!surfaces.intersect(hit, ray)) {
            return scene.getBackColor();
        }
        return hit.surface.getShader().shade(hit, ray, this, depth);
    }

    @Override
    public List<Light> lights() {
        return scene.getLights();
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        stats.shadow++;
        return !surfaces.intersect(shadowHit, SecondaryRays.shadowRay(hit, lightPosition));
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        stats.reflection++;
        return shade(SecondaryRays.reflectionRay(hit, direction), depth);
    }
}
