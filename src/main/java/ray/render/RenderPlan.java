package ray.render;

import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import ray.accel.Acceleration;
import ray.scene.Scene;
import ray.shading.Effect;
import ray.shading.Glazed;
import ray.shading.Shader;
import ray.surface.Surface;

/**
 * Which effects a render simulates, decided from the scene alone before any ray is traced: a scene
 * pays only for what it uses. The plan walks the surface tree ({@link Surface#children()}) and every
 * reachable shader (with its {@link Shader#parts()}), and counts the {@link Effect}s each reports.
 * The renderer takes its sample grid and the primitive count for the intersection counter from here.
 */
public final class RenderPlan {

    /** The scene as rendered: {@link #written} seen from its camera's frame, unless {@link #withWorldFrame} asked otherwise. */
    private final Scene scene;
    /** The scene as its file (or code) gave it. */
    private final Scene written;
    private final int gridSide;
    private final SamplePattern pattern;
    private final long primitives;
    /** Where rays leaving a surface start: {@link RayOffsets#SCALED} unless a study of the alternatives asks otherwise. */
    private final RayOffsets offsets;
    /**
     * The most hits a path of mirror rays may have, the camera ray's included: {@link #SHADERS_OWN_DEPTH}
     * (each shader's own cap) unless a study of what depth buys asks for fewer.
     */
    private final int pathHits;
    /** {@link #pathHits} when no cap is asked for: the shaders' own (the course's 12 hits, a glaze's 12 bounces) apply. */
    public static final int SHADERS_OWN_DEPTH = Integer.MAX_VALUE;
    /** The pixels rendered: the whole image unless a window of it is asked for. */
    private final PixelWindow window;
    /** How the framework's searches run: {@link Acceleration#BVH} unless {@code --accel none} asks otherwise. */
    private final Acceleration acceleration;
    /** What each running effect counts (lights, shaders, groups, triangles, grid side), in Effect order. */
    private final Map<Effect, String> running = new EnumMap<>(Effect.class);
    /**
     * What the scene's hierarchies count ("2 meshes, 86,528 triangles"), or null when it has none:
     * kept apart from {@link #running} so that a plan made without acceleration can be made with it again.
     */
    private final String trees;
    /** How many shaders trace mirror rays ("2 shaders"), or null: the reflection entry adds the plan's depth ({@link #reflection}). */
    private final String mirrorShaders;

    private RenderPlan(Scene scene, int samplesPerPixel, SamplePattern pattern) {
        // Every render runs in the camera's frame: the same image, with hit points as exact as the
        // scene's size allows wherever the scene sits (CameraFrame).
        this.written = scene;
        this.scene = scene.inCameraFrame();
        this.gridSide = Renderer.gridSide(samplesPerPixel);
        this.pattern = pattern;
        this.offsets = RayOffsets.SCALED;
        this.pathHits = SHADERS_OWN_DEPTH;
        this.window = PixelWindow.whole(scene.getWidth(), scene.getHeight());
        this.acceleration = Acceleration.BVH;
        Walk walk = new Walk();
        walk.surface(scene.getSurfaces());
        this.primitives = walk.primitives;
        int lights = scene.getLights().size();
        // Lighting and shadows need a light as well as a shader that asks for them.
        if (lights > 0 && walk.count(Effect.LIGHTING) > 0) {
            running.put(Effect.LIGHTING, count(walk.count(Effect.LIGHTING), "shader"));
            running.put(Effect.SHADOWS, count(lights, "light"));
        }
        // A texture replaces the diffuse color of a lit shader, so without a light no lookup is needed.
        if (lights > 0 && walk.count(Effect.TEXTURES) > 0) {
            running.put(Effect.TEXTURES, count(walk.count(Effect.TEXTURES), "shader"));
        }
        if (walk.count(Effect.SPECULAR) > 0) {
            running.put(Effect.SPECULAR, count(walk.count(Effect.SPECULAR), "shader"));
        }
        this.mirrorShaders = walk.count(Effect.REFLECTION) == 0 ? null : count(walk.count(Effect.REFLECTION), "shader");
        if (mirrorShaders != null) {
            running.put(Effect.REFLECTION, reflection());
        }
        if (gridSide > 1) {
            running.put(Effect.ANTIALIASING, gridSide + "x" + gridSide + (pattern.isJittered() ? " jittered" : ""));
        }
        if (walk.count(Effect.TRANSFORMS) > 0) {
            running.put(Effect.TRANSFORMS, count(walk.count(Effect.TRANSFORMS), "group"));
        }
        if (walk.count(Effect.VERTEX_NORMALS) > 0) {
            running.put(Effect.VERTEX_NORMALS, count(walk.count(Effect.VERTEX_NORMALS), "triangle"));
        }
        this.trees = walk.count(Effect.ACCELERATION) == 0 ? null
                : count(walk.count(Effect.ACCELERATION), "mesh", "meshes") + ", " + count(walk.treeTriangles, "triangle");
        if (trees != null) {
            running.put(Effect.ACCELERATION, trees);
        }
    }

    /** The plan for the scene as written, with its own {@code <samples>} on the regular grid. */
    public static RenderPlan of(Scene scene) {
        return of(scene, 0);
    }

    /** The plan for the scene rendered with {@code samplesPerPixel} samples (its own when 0) on the regular grid. */
    public static RenderPlan of(Scene scene, int samplesPerPixel) {
        return of(scene, samplesPerPixel, SamplePattern.GRID);
    }

    /** The plan for the scene rendered with {@code samplesPerPixel} samples (its own when 0) placed by {@code pattern}. */
    public static RenderPlan of(Scene scene, int samplesPerPixel, SamplePattern pattern) {
        if (samplesPerPixel < 0) {
            throw new IllegalArgumentException("samples must be ≥ 0, got " + samplesPerPixel);
        }
        return new RenderPlan(scene, samplesPerPixel > 0 ? samplesPerPixel : scene.getSamples(), pattern);
    }

    /** A copy of {@code plan} with other offsets or window; the effects stay those of the scene. */
    private RenderPlan(RenderPlan plan, RayOffsets offsets, PixelWindow window, Acceleration acceleration) {
        this(plan, offsets, window, acceleration, plan.pathHits);
    }

    /** A copy of {@code plan} with other offsets, window, acceleration or depth; the effects stay those of the scene. */
    private RenderPlan(RenderPlan plan, RayOffsets offsets, PixelWindow window, Acceleration acceleration, int pathHits) {
        this.written = plan.written;
        this.scene = plan.scene;
        this.gridSide = plan.gridSide;
        this.pattern = plan.pattern;
        this.primitives = plan.primitives;
        this.running.putAll(plan.running);
        this.trees = plan.trees;
        this.offsets = offsets;
        this.window = window;
        this.acceleration = acceleration;
        this.pathHits = pathHits;
        this.mirrorShaders = plan.mirrorShaders;
        if (mirrorShaders != null) {
            running.put(Effect.REFLECTION, reflection());
        }
        running.remove(Effect.ACCELERATION);
        if (acceleration.accelerated() && trees != null) {
            running.put(Effect.ACCELERATION, acceleration == Acceleration.STUDENT ? trees + ", your BvhTree" : trees);
        }
    }

    /** A copy of {@code plan} that renders {@code scene} (the written scene or its camera frame). */
    private RenderPlan(RenderPlan plan, Scene scene) {
        this.written = plan.written;
        this.scene = scene;
        this.gridSide = plan.gridSide;
        this.pattern = plan.pattern;
        this.primitives = plan.primitives;
        this.running.putAll(plan.running);
        this.trees = plan.trees;
        this.offsets = plan.offsets;
        this.pathHits = plan.pathHits;
        this.mirrorShaders = plan.mirrorShaders;
        this.window = plan.window;
        this.acceleration = plan.acceleration;
    }

    /**
     * This plan rendering the scene in its own coordinates, as renderers did before the camera's
     * frame (for showing what the frame buys far from the origin; renders use the camera's frame).
     */
    public RenderPlan withWorldFrame() {
        return new RenderPlan(this, written);
    }

    /** This plan with secondary rays started by {@code rule} (for comparing the rules; renders use SCALED). */
    public RenderPlan withOffsets(RayOffsets rule) {
        return new RenderPlan(this, rule, window, acceleration);
    }

    /**
     * This plan with the framework's searches run as {@code mode} says: {@link Acceleration#NONE}
     * renders the same image by plain linear loops (and drops the bvh effect).
     */
    public RenderPlan withAcceleration(Acceleration mode) {
        return new RenderPlan(this, offsets, window, mode);
    }

    public Acceleration acceleration() {
        return acceleration;
    }

    /**
     * This plan with paths of mirror rays cut after {@code hits} hits (the camera ray's first): a
     * mirror ray that would make hit {@code hits + 1} is not traced and brings back black, as the
     * course's depth limit does at 12. For measuring what depth buys; renders use the shaders' own cap.
     */
    public RenderPlan withPathHits(int hits) {
        if (hits < 1) {
            throw new IllegalArgumentException("a path has at least its camera ray's hit; got " + hits);
        }
        return new RenderPlan(this, offsets, window, acceleration, hits);
    }

    /** The reflection effect's entry: its shaders and the depth this plan lets paths reach ("2 shaders, depth 12"). */
    private String reflection() {
        return mirrorShaders + ", depth " + (pathHits == SHADERS_OWN_DEPTH ? Glazed.MAX_DEPTH : pathHits);
    }

    /** The most hits a path may have, or {@link #SHADERS_OWN_DEPTH}. */
    public int pathHits() {
        return pathHits;
    }

    /**
     * This plan rendering only {@code part} of the image, to an image of the window's size.
     *
     * @throws IllegalArgumentException when the window does not lie inside the scene's image
     */
    public RenderPlan withWindow(PixelWindow part) {
        if (!part.fitsIn(scene.getWidth(), scene.getHeight())) {
            throw new IllegalArgumentException("the window " + part + " does not fit in the " + scene.getWidth() + "x"
                    + scene.getHeight() + " image");
        }
        return new RenderPlan(this, offsets, part, acceleration);
    }

    public Scene scene() {
        return scene;
    }

    public RayOffsets offsets() {
        return offsets;
    }

    public PixelWindow window() {
        return window;
    }

    public boolean runs(Effect effect) {
        return running.containsKey(effect);
    }

    /** Where each pixel's samples fall: the regular grid or jittered. */
    public SamplePattern pattern() {
        return pattern;
    }

    /** n, the side of the per-pixel sample grid; n² camera rays per pixel. */
    public int gridSide() {
        return gridSide;
    }

    /**
     * The leaves of the surface tree (spheres, triangles, ...; a surface reached twice counts twice).
     * Every ray is tested against each of them once by the linear closest-hit loop of Group.
     */
    public long primitives() {
        return primitives;
    }

    /** The effects that run, each with what it counts, e.g. {@code shadows(2 lights)}. */
    public List<String> effects() {
        List<String> list = new ArrayList<>();
        running.forEach((effect, what) -> list.add(effect.label + "(" + what + ")"));
        return Collections.unmodifiableList(list);
    }

    /** The effects this scene does not call for, by label. */
    public List<String> skipped() {
        List<String> list = new ArrayList<>();
        for (Effect effect : Effect.values()) {
            if (!running.containsKey(effect)) {
                list.add(effect.label);
            }
        }
        return Collections.unmodifiableList(list);
    }

    /** One line: {@code effects: shadows(2 lights) specular(1 shader); skipped: reflection, antialiasing}. */
    public String describe() {
        List<String> effects = effects();
        List<String> skipped = skipped();
        return "effects: " + (effects.isEmpty() ? "none" : String.join(" ", effects))
                + "; skipped: " + (skipped.isEmpty() ? "none" : String.join(", ", skipped));
    }

    @Override
    public String toString() {
        return describe();
    }

    private static String count(long n, String noun) {
        return count(n, noun, noun + "s");
    }

    /** n and the noun, with thousands separated by commas (86,528 triangles). */
    private static String count(long n, String noun, String plural) {
        return String.format(java.util.Locale.ROOT, "%,d %s", n, n == 1 ? noun : plural);
    }

    /**
     * One pass over the surface tree: how many surfaces and distinct shaders (by identity, a glaze's
     * substrate too) call for each effect, and how many primitives there are.
     */
    private static final class Walk {
        final Set<Shader> shaders = Collections.newSetFromMap(new IdentityHashMap<>());
        final Map<Effect, Long> counts = new EnumMap<>(Effect.class);
        long primitives;
        /** Triangles in the meshes and boxes searched through a hierarchy. */
        long treeTriangles;

        long count(Effect effect) {
            return counts.getOrDefault(effect, 0L);
        }

        void surface(Surface s) {
            Set<Effect> own = s.effects();
            note(own);
            if (own.contains(Effect.ACCELERATION)) {
                treeTriangles += s.children().size();
            }
            if (s.isPrimitive()) {
                primitives++;
                shader(s.getShader());
                return;
            }
            // A group's parts (an empty group tests nothing).
            for (Surface child : s.children()) {
                surface(child);
            }
        }

        void shader(Shader shader) {
            if (shader == null || !shaders.add(shader)) {
                return;
            }
            note(shader.effects());
            for (Shader part : shader.parts()) {
                shader(part);
            }
        }

        private void note(Set<Effect> effects) {
            for (Effect e : effects) {
                counts.merge(e, 1L, Long::sum);
            }
        }
    }
}
