package ray.render;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Surface;

/**
 * What the framework keeps of the ray tracer ({@link RayTracer}, whose {@code shadeRay} students
 * write): the scene's surfaces to search, its background color, and how a hit gets shaded. The
 * renderer makes one per shading context ({@link SceneShading}) and calls {@code shadeRay} for every
 * camera ray and every mirror ray.
 */
public abstract class SceneTracer {
    private Surface surfaces;
    private Vec3 backColor = Vec3.ZERO;
    private HitShading hits;
    private int maxDepth = Integer.MAX_VALUE;

    /** Gives the tracer its scene: the surfaces (the scene's group), the background color and the shading of hits; no depth limit. */
    public void use(Surface surfaces, Vec3 backColor, HitShading hits) {
        use(surfaces, backColor, hits, Integer.MAX_VALUE);
    }

    /** As {@link #use(Surface, Vec3, HitShading)}, with the depth from which rays bring back black ({@link #maxDepth()}). */
    public void use(Surface surfaces, Vec3 backColor, HitShading hits, int maxDepth) {
        this.surfaces = surfaces;
        this.backColor = backColor;
        this.hits = hits;
        this.maxDepth = maxDepth;
    }

    /**
     * The course's limit on a path of mirror rays: a ray of depth {@code maxDepth()} or more (camera
     * rays have depth 0) brings back black and is not traced ({@link ray.shading.Course#maxRayDepth()}:
     * 12 under 2019's conventions, none under 2017's).
     */
    public int maxDepth() {
        return maxDepth;
    }

    /** The scene's surfaces, as one: {@code surfaces().intersect(hit, ray)} finds the ray's closest hit. */
    public Surface surfaces() {
        return surfaces;
    }

    /** The scene's background color: what a ray that hits nothing brings back. */
    public Vec3 backgroundColor() {
        return backColor;
    }

    /**
     * The light that leaves {@code hit}, the closest hit of {@code ray}, back along the ray: the hit
     * surface's shader shades it (with the scene's lights, its shadow rays and, for a mirror, a ray of
     * depth {@code depth} + 1 traced by {@code shadeRay} again).
     */
    public Vec3 shade(IntersectionRecord hit, Ray ray, int depth) {
        return hits.shade(hit, ray, depth);
    }

    /** Checks nothing: the renderer gives the tracer its scene ({@link #use}). */
    public void complete() {
    }

    /**
     * The radiance that arrives along {@code ray} (of recursion depth {@code depth}: 0 for camera rays),
     * as linear RGB.
     */
    public abstract Vec3 shadeRay(Ray ray, int depth);
}
