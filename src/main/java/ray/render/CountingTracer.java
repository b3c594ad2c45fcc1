package ray.render;

import java.util.IdentityHashMap;
import java.util.Map;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.shading.Effect;
import ray.shading.Shader;

/**
 * The renderer's tracer for one thread: {@link SceneTracer}'s rules, counting the work as it goes
 * (camera, shadow and reflection rays, and the specular terms of the shaders that have one), so
 * that {@code --stats} shows what a scene costs and tests can prove that a scene without an effect
 * does none of its work. Not shared between threads.
 */
final class CountingTracer extends SceneTracer {
    private final long primitives;
    private final RayStats stats = new RayStats();
    /** Whether each shader met so far evaluates a specular term per light. */
    private final Map<Shader, Boolean> specular = new IdentityHashMap<>();

    CountingTracer(RenderPlan plan) {
        super(plan.scene(), plan.offsets());
        this.primitives = plan.primitives();
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
        return radiance(ray, 0);
    }

    /** A shader with a specular term evaluates it once per light, shadowed or not. */
    @Override
    protected Vec3 shade(IntersectionRecord hit, Ray ray, int depth) {
        Shader shader = hit.surface.getShader();
        if (specular.computeIfAbsent(shader, s -> s.allEffects().contains(Effect.SPECULAR))) {
            stats.specular += lights().size();
        }
        return super.shade(hit, ray, depth);
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        stats.shadow++;
        return super.unoccluded(hit, lightPosition);
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        stats.reflection++;
        return super.radiance(hit, direction, depth);
    }
}
