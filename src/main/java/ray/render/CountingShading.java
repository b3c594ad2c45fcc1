package ray.render;

import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.SearchCounter;
import ray.math.Vec3;
import ray.shading.Effect;
import ray.shading.Shader;
import ray.surface.SurfaceKind;

/**
 * The renderer's shading context for one thread: {@link SceneShading}'s rules, counting the work as it goes
 * (camera, shadow and reflection rays, the specular terms and texture lookups of the shaders that
 * have them), so
 * that {@code --stats} shows what a scene costs and tests can prove that a scene without an effect
 * does none of its work; and, when asked, what each camera ray hit first ({@link #cameraKind()},
 * for {@link PixelKinds}). Not shared between threads.
 */
final class CountingShading extends SceneShading {
    private final SearchCounter counter;
    private final RayStats stats = new RayStats();
    /** The effects of each shader met so far, its parts' included. */
    private final Map<Shader, Set<Effect>> effects = new IdentityHashMap<>();
    /** Whether camera rays' closest hits are noted; when false nothing below is touched. */
    private final boolean recordKinds;
    /** The kind the last camera ray hit first, when recording. */
    private SurfaceKind cameraKind = SurfaceKind.BACKGROUND;
    /** Whether the last camera ray's closest hit is yet to be shaded: the next {@link #shade} is its. */
    private boolean cameraHitPending;

    CountingShading(RenderPlan plan) {
        this(plan, false);
    }

    /** @param recordKinds whether to note what each camera ray hits first, for {@link #cameraKind()} */
    CountingShading(RenderPlan plan, boolean recordKinds) {
        this(plan, new SearchCounter(), recordKinds);
    }

    private CountingShading(RenderPlan plan, SearchCounter counter, boolean recordKinds) {
        super(plan.scene(), plan.offsets(), plan.scene().getSurfaces().searchCopy(plan.acceleration(), counter),
                plan.acceleration(), plan.pathHits());
        this.counter = counter;
        this.recordKinds = recordKinds;
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
        if (recordKinds) {
            cameraKind = SurfaceKind.BACKGROUND;
            cameraHitPending = true;
        }
        return radiance(ray, 0);
    }

    /**
     * What the last camera ray ({@link #cameraRadiance}) hit first, when this shading records kinds:
     * the kind of the primitive its closest hit names, or the background on a miss. Only a hit is
     * shaded, and a camera ray's hit is shaded before any ray its shader sends, so the first
     * {@link #shade} after a camera ray is that ray's closest hit: the kind comes from the record the
     * scene's own search (the student's code) filled, and the search itself is not repeated.
     */
    SurfaceKind cameraKind() {
        return cameraKind;
    }

    /**
     * A shader with a specular term evaluates it once per light, shadowed or not; a textured one looks
     * its texture up once per hit when there is a light to use the color (see DirectLighting.shade).
     */
    @Override
    protected Vec3 shade(IntersectionRecord hit, Ray ray, int depth) {
        if (recordKinds && cameraHitPending) {
            cameraKind = SurfaceKind.of(hit.surface);
            cameraHitPending = false;
        }
        Shader shader = hit.surface.getShader();
        if (!shader.evaluatesAt(hit, ray)) {
            return super.shade(hit, ray, depth);
        }
        Set<Effect> shaderEffects = effects.computeIfAbsent(shader, Shader::allEffects);
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
        if (!withinDepth(depth)) {
            return Vec3.ZERO;
        }
        // A ray past the course's limit goes to the tracer, whose shadeRay returns black without
        // tracing it (students' code included): it is no reflection ray.
        if (tracedByTheCourse(depth)) {
            stats.reflection++;
            counter.searchingFor(SearchCounter.REFLECTION);
        }
        return super.radiance(hit, direction, depth);
    }
}
