package ray.accuracy;

import java.util.function.UnaryOperator;
import ray.accel.Acceleration;
import ray.render.RayOffsets;
import ray.render.RenderPlan;
import ray.render.SamplePattern;
import ray.scene.Scene;
import ray.scene.SceneOptions;
import ray.surface.Surface;

/**
 * One choice a renderer makes, as a point of a {@link Sweep}: how many samples per pixel and where
 * they fall, where secondary rays start, whether the framework's searches are accelerated, and (for the instructor's sweeps) which intersection code
 * the surfaces run. Everything not named here is the framework's own choice.
 */
public final class Setting {
    /** The label in tables and plots, e.g. "jittered 16" or "float". */
    public final String label;
    /** Samples per pixel, or 0 for the scene's own {@code <samples>}. */
    public final int samples;
    public final SamplePattern pattern;
    public final RayOffsets offsets;
    /** How the framework searches: with its BVH and any-hit shadow rays, or by linear loops. */
    public final Acceleration acceleration;
    /** Rewrites the scene's surface tree; null for the framework's own intersection code. */
    private final UnaryOperator<Surface> surfaces;
    /** The most hits along a path of mirror rays ({@link RenderPlan#withPathHits}), or the shaders' own cap. */
    private final int pathHits;
    /** How the scene is loaded again for this setting (its BRDFs replaced), or null to render it as loaded. */
    private UnaryOperator<SceneOptions> reload;

    private Setting(String label, int samples, SamplePattern pattern, RayOffsets offsets, UnaryOperator<Surface> surfaces) {
        this(label, samples, pattern, offsets, surfaces, Acceleration.BVH);
    }

    private Setting(String label, int samples, SamplePattern pattern, RayOffsets offsets, UnaryOperator<Surface> surfaces,
            Acceleration acceleration) {
        this(label, samples, pattern, offsets, surfaces, acceleration, RenderPlan.SHADERS_OWN_DEPTH);
    }

    private Setting(String label, int samples, SamplePattern pattern, RayOffsets offsets, UnaryOperator<Surface> surfaces,
            Acceleration acceleration, int pathHits) {
        this.pathHits = pathHits;
        this.label = label;
        this.samples = samples;
        this.pattern = pattern;
        this.offsets = offsets;
        this.surfaces = surfaces;
        this.acceleration = acceleration;
    }

    /** The scene's own samples, searched as {@code mode} says (the image is the same; the time is not). */
    public static Setting acceleration(String label, Acceleration mode) {
        return new Setting(label, 0, SamplePattern.GRID, RayOffsets.SCALED, null, mode);
    }

    /** The scene's own samples with paths of mirror rays cut after {@code hits} hits. */
    public static Setting pathHits(String label, int hits) {
        return new Setting(label, 0, SamplePattern.GRID, RayOffsets.SCALED, null, Acceleration.BVH, hits);
    }

    /** The framework's choices at the scene's own samples, on the regular grid. */
    public static Setting framework(String label) {
        return new Setting(label, 0, SamplePattern.GRID, RayOffsets.SCALED, null);
    }

    /** {@code samples} per pixel placed by {@code pattern}; everything else the framework's. */
    public static Setting sampled(String label, int samples, SamplePattern pattern) {
        return new Setting(label, samples, pattern, RayOffsets.SCALED, null);
    }

    /** The scene's own samples with secondary rays started by {@code rule}. */
    public static Setting offsets(String label, RayOffsets rule) {
        return new Setting(label, 0, SamplePattern.GRID, rule, null);
    }

    /**
     * The scene's own samples with its surfaces rewritten by {@code surfaces} (e.g. every sphere
     * tested by another formula). The rewrite must keep each hit naming a primitive of the original
     * scene, so shading and offsets stay the framework's.
     */
    public static Setting surfaces(String label, UnaryOperator<Surface> surfaces) {
        return new Setting(label, 0, SamplePattern.GRID, RayOffsets.SCALED, surfaces);
    }

    /**
     * The scene's own samples, the scene loaded again with the options {@code reload} makes (BRDFs
     * replaced by an approximation, say): a setting of the shading rather than of the rays.
     */
    public static Setting reloaded(String label, UnaryOperator<SceneOptions> reload) {
        Setting setting = new Setting(label, 0, SamplePattern.GRID, RayOffsets.SCALED, null);
        setting.reload = reload;
        return setting;
    }

    /** This setting with secondary rays started by {@code rule} instead, under another label. */
    public Setting withOffsets(String newLabel, RayOffsets rule) {
        Setting setting = new Setting(newLabel, samples, pattern, rule, surfaces, acceleration, pathHits);
        setting.reload = reload;
        return setting;
    }

    /** The plan that renders {@code scene} with this setting (the whole image). */
    public RenderPlan plan(Scene scene) {
        Scene rendered = reload != null ? scene.reload(reload) : scene;
        if (surfaces != null) {
            rendered = SceneCopy.withSurfaces(scene, surfaces.apply(scene.getSurfaces()));
        }
        RenderPlan plan = RenderPlan.of(rendered, samples, pattern).withOffsets(offsets).withAcceleration(acceleration);
        return pathHits == RenderPlan.SHADERS_OWN_DEPTH ? plan : plan.withPathHits(pathHits);
    }

    @Override
    public String toString() {
        return label;
    }
}
