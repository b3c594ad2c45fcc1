package ray.render;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Light;
import ray.shading.ShadingContext;
import ray.surface.HitGeometry;
import ray.surface.Surface;

/**
 * The scene's shading context, the renderer's tracing rules in one place: a ray's radiance is what
 * the ray tracer's {@code shadeRay} returns ({@link RayTracer}: its closest hit, by the scene's group,
 * shaded by the hit primitive's shader, or the background on a miss);
 * shadow and reflection rays start off the surface by the plan's {@link RayOffsets}, from the
 * hit's geometry that the scene measures after the search ({@link Scene#hitGeometry}). The renderer
 * counts rays with a subclass ({@link CountingShading}); {@code ray1 trace} uses one to take a
 * pixel apart. One per thread: it keeps the last hit's geometry, which a shader's several shadow
 * rays share.
 */
public class SceneShading implements ShadingContext {
    private final Scene scene;
    private final Surface surfaces;
    private final RayOffsets offsets;
    /** The most hits a path may have ({@link RenderPlan#pathHits}): a mirror ray past it is not traced. */
    private final int pathHits;
    /** Whether shadow rays ask "anything in the way?" (stopping at the first blocker) or search for the closest hit. */
    private final boolean anyHitShadows;
    /** Scratch record for shadow tests, whose hit is never read. */
    private final IntersectionRecord shadowHit = new IntersectionRecord();
    private IntersectionRecord lastHit;
    private Vec3 lastLocation;
    private HitGeometry lastGeometry;
    /** The ray tracer whose shadeRay gives every ray's radiance (the students' code, when it is a task). */
    private final SceneTracer tracer = new RayTracer();

    public SceneShading(Scene scene) {
        this(scene, RayOffsets.SCALED);
    }

    public SceneShading(Scene scene, RayOffsets offsets) {
        this(scene, offsets, scene.getSurfaces(), Acceleration.BVH, RenderPlan.SHADERS_OWN_DEPTH);
    }

    /**
     * A shading context that searches {@code surfaces} (the scene's, or a counting copy, {@link Surface#searchCopy},
     * of them), with shadow rays as {@code acceleration} says.
     */
    protected SceneShading(Scene scene, RayOffsets offsets, Surface surfaces, Acceleration acceleration, int pathHits) {
        this.scene = scene;
        this.pathHits = pathHits;
        this.surfaces = surfaces;
        this.offsets = offsets;
        this.anyHitShadows = acceleration.accelerated();
        tracer.use(surfaces, scene.getBackColor(), this::shade, scene.getCourse().maxRayDepth());
        tracer.complete();
    }

    public Scene scene() {
        return scene;
    }

    /** The radiance that arrives along {@code ray}, a ray of recursion depth {@code depth}: the ray tracer's {@code shadeRay}. */
    public Vec3 radiance(Ray ray, int depth) {
        return tracer.shadeRay(ray, depth);
    }

    /** Shades a closest hit of {@code ray} with the hit primitive's shader. */
    protected Vec3 shade(IntersectionRecord hit, Ray ray, int depth) {
        return hit.surface.getShader().shade(hit, ray, this, depth);
    }

    @Override
    public List<Light> lights() {
        return scene.getLights();
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        Ray shadowRay = shadowRay(hit, lightPosition);
        return anyHitShadows ? !surfaces.intersectsAny(shadowRay) : !surfaces.intersect(shadowHit, shadowRay);
    }

    /** Whether a mirror ray of recursion depth {@code depth} (0 for camera rays) is asked of the tracer: the plan's cap allows its hit, number depth + 1. */
    protected boolean withinDepth(int depth) {
        return depth < pathHits;
    }

    /** Whether the course's tracer traces a ray of depth {@code depth} (a correct one returns black past its limit, untraced). */
    protected boolean tracedByTheCourse(int depth) {
        return depth < tracer.maxDepth();
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        return withinDepth(depth) ? radiance(reflectionRay(hit, direction), depth) : Vec3.ZERO;
    }

    /** The shadow ray that {@link #unoccluded} traces from {@code hit} toward {@code lightPosition}. */
    public Ray shadowRay(IntersectionRecord hit, Vec3 lightPosition) {
        return offsets.shadowRay(geometry(hit), lightPosition);
    }

    /** The reflection ray that {@link #radiance(IntersectionRecord, Vec3, int)} traces. */
    public Ray reflectionRay(IntersectionRecord hit, Vec3 direction) {
        return offsets.reflectionRay(geometry(hit), direction);
    }

    /** The hit's geometry, measured once per hit (a hit's location object changes only with a new hit). */
    private HitGeometry geometry(IntersectionRecord hit) {
        if (hit != lastHit || hit.location != lastLocation) {
            lastGeometry = scene.hitGeometry(hit);
            lastHit = hit;
            lastLocation = hit.location;
        }
        return lastGeometry;
    }
}
