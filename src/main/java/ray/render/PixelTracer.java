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
    private final long primitives;
    private final boolean skipsZeroWork;
    private final RayOffsets offsets;
    private final RayStats stats = new RayStats();
    /** Scratch record for shadow tests, whose hit is never read. */
    private final IntersectionRecord shadowHit = new IntersectionRecord();

    /** @param skipsZeroWork false only for the test mode that traces every shadow and reflection ray */
    PixelTracer(RenderPlan plan, boolean skipsZeroWork) {
        this.scene = plan.scene();
        this.surfaces = scene.getSurfaces();
        this.primitives = plan.primitives();
        this.skipsZeroWork = skipsZeroWork;
        this.offsets = plan.offsets();
    }

    /**
     * The counts so far. Intersection tests are not counted per ray: the linear closest-hit loop
     * tests every ray against each of the plan's primitives, so they are exactly rays × primitives.
     */
    RayStats stats() {
        stats.intersectionTests = stats.total() * primitives;
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
        return !surfaces.intersect(shadowHit, offsets.shadowRay(hit, lightPosition));
    }

    @Override
    public void specularEvaluated() {
        stats.specular++;
    }

    @Override
    public boolean skipsZeroWork() {
        return skipsZeroWork;
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        stats.reflection++;
        return shade(offsets.reflectionRay(hit, direction), depth);
    }
}
