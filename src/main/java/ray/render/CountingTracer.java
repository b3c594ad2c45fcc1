package ray.render;

import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.SearchCounter;
import ray.accel.SearchTree;
import ray.math.Vec3;
import ray.shading.Effect;
import ray.shading.Shader;

/**
 * The renderer's tracer for one thread: {@link SceneTracer}'s rules, counting the work as it goes
 * (camera, shadow and reflection rays, the specular terms and texture lookups of the shaders that
 * have them), so
 * that {@code --stats} shows what a scene costs and tests can prove that a scene without an effect
 * does none of its work. Not shared between threads.
 */
final class CountingTracer extends SceneTracer {
    private final SearchCounter counter;
    private final RayStats stats = new RayStats();
    /** The effects of each shader met so far, its parts' included. */
    private final Map<Shader, Set<Effect>> effects = new IdentityHashMap<>();

    CountingTracer(RenderPlan plan) {
        this(plan, new SearchCounter());
    }

    private CountingTracer(RenderPlan plan, SearchCounter counter) {
        super(plan.scene(), plan.offsets(), SearchTree.of(plan.scene().getSurfaces(), plan.acceleration(), counter),
                plan.acceleration());
        this.counter = counter;
    }

    /** The counts so far: rays and shading work counted here, intersection tests and boxes where they were made. */
    RayStats stats() {
        stats.countedSearches(counter);
        return stats;
    }

    /** The radiance a camera ray sees. */
    Vec3 cameraRadiance(Ray ray) {
        stats.camera++;
        counter.searchingFor(SearchCounter.CAMERA);
        return radiance(ray, 0);
    }

    /**
     * A shader with a specular term evaluates it once per light, shadowed or not; a textured one looks
     * its texture up once per hit when there is a light to use the color (see DirectLighting.shade).
     */
    @Override
    protected Vec3 shade(IntersectionRecord hit, Ray ray, int depth) {
        Set<Effect> shaderEffects = effects.computeIfAbsent(hit.surface.getShader(), Shader::allEffects);
        int lights = lights().size();
        if (shaderEffects.contains(Effect.SPECULAR)) {
            stats.specular += lights;
        }
        if (lights > 0 && shaderEffects.contains(Effect.TEXTURES)) {
            stats.textureLookups++;
        }
        return super.shade(hit, ray, depth);
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        stats.shadow++;
        counter.searchingFor(SearchCounter.SHADOW);
        return super.unoccluded(hit, lightPosition);
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        stats.reflection++;
        counter.searchingFor(SearchCounter.REFLECTION);
        return super.radiance(hit, direction, depth);
    }
}
