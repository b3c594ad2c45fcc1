package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.util.List;
import org.junit.Test;
import ray.image.Image;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Effect;
import ray.shading.Glazed;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.Phong;
import ray.shading.RGBNormals;
import ray.shading.RepeatTexture;
import ray.shading.Shader;
import ray.surface.Group;
import ray.surface.Placement;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * RenderPlan.of decides the effects from the scene alone: lights and lit shaders, Phong shaders
 * (a glaze's substrate too), Glazed shaders, the sample grid, transformed groups and smooth
 * triangles, and counts the primitives. Scenes are built in code and never rendered, so this
 * needs no student code.
 */
public class RenderPlanTest {

    private static Scene emptyScene() {
        return TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 5, 3), 5, 3);
    }

    private static Surface sphere(Shader shader) {
        Sphere s = new Sphere();
        s.setShader(shader);
        return s.complete();
    }

    private static Surface flatTriangle(Shader shader) {
        return TestScenes.plane(0, true, shader);
    }

    private static Surface smoothTriangle(Shader shader) {
        Triangle t = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0), v(0, 0, 1), v(0, 0, 1), v(0, 0, 1));
        t.setShader(shader);
        return t;
    }

    @Test
    public void noLightsMeansNoLightingAndNoShadows() {
        Scene scene = emptyScene();
        scene.addSurface(flatTriangle(new Lambertian()));
        scene.complete();
        RenderPlan plan = RenderPlan.of(scene);
        assertFalse(plan.runs(Effect.LIGHTING));
        assertFalse(plan.runs(Effect.SHADOWS));
        assertEquals(List.of(), plan.effects());
        assertEquals("effects: none; skipped: lighting, shadows, specular, textures, reflection, antialiasing, transforms, vertex normals, bvh",
                plan.describe());
    }

    @Test
    public void lightsWithoutALitShaderRunNoLighting() {
        Scene scene = emptyScene();
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.addSurface(flatTriangle(new RGBNormals()));
        scene.complete();
        RenderPlan plan = RenderPlan.of(scene);
        assertFalse(plan.runs(Effect.LIGHTING));
        assertFalse(plan.runs(Effect.SHADOWS));
    }

    @Test
    public void lightsAndALambertianRunLightingAndShadowsCountingLights() {
        Scene scene = emptyScene();
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.addLight(new Light(v(1, 0, 3), Vec3.ONE));
        scene.addSurface(flatTriangle(new Lambertian()));
        scene.complete();
        RenderPlan plan = RenderPlan.of(scene);
        assertEquals(List.of("lighting(1 shader)", "shadows(2 lights)"), plan.effects());
        assertFalse("Lambertian has no specular term", plan.runs(Effect.SPECULAR));
    }

    @Test
    public void specularCountsDistinctPhongShadersIncludingAGlazeSubstrate() {
        Scene scene = emptyScene();
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        Phong shared = new Phong();
        Glazed glazed = new Glazed();
        glazed.setSubstrate(new Phong());
        scene.addSurface(sphere(shared));
        scene.addSurface(flatTriangle(shared));
        scene.addSurface(sphere(glazed));
        scene.addSurface(sphere(new Lambertian()));
        scene.complete();
        RenderPlan plan = RenderPlan.of(scene);
        // Lit: the shared Phong, the substrate Phong and the Lambertian (the glaze itself uses no lights).
        assertEquals(List.of("lighting(3 shaders)", "shadows(1 light)", "specular(2 shaders)",
                "reflection(1 shader, depth " + Glazed.MAX_DEPTH + ")"), plan.effects());
    }

    @Test
    public void noGlazedShaderSkipsReflection() {
        Scene scene = emptyScene();
        scene.addSurface(sphere(new Phong()));
        scene.complete();
        assertFalse(RenderPlan.of(scene).runs(Effect.REFLECTION));
        assertTrue(RenderPlan.of(scene).skipped().contains("reflection"));
    }

    @Test
    public void antialiasingRunsOnlyForAGridLargerThanOne() {
        Scene scene = emptyScene();
        scene.addSurface(sphere(new Lambertian()));
        scene.setSamples(9);
        scene.complete();
        assertEquals(List.of("antialiasing(3x3)"), RenderPlan.of(scene).effects());
        assertEquals("an override of 1 sample", 1, RenderPlan.of(scene, 1).gridSide());
        assertFalse(RenderPlan.of(scene, 1).runs(Effect.ANTIALIASING));
        assertFalse("2 samples round to a 1×1 grid", RenderPlan.of(scene, 2).runs(Effect.ANTIALIASING));
        assertEquals("3 samples round to 2×2", 2, RenderPlan.of(scene, 3).gridSide());
        assertEquals("0 means the scene's own samples", 3, RenderPlan.of(scene, 0).gridSide());
    }

    @Test
    public void onlyAGroupWithATransformCountsAsTransforms() {
        Scene plain = emptyScene();
        Group identity = new Group();
        identity.addSurface(sphere(new Lambertian()));
        plain.addSurface(identity.complete());
        plain.complete();
        assertFalse(RenderPlan.of(plain).runs(Effect.TRANSFORMS));

        Scene moved = emptyScene();
        Group outer = new Group();
        Group inner = new Group();
        inner.addSurface(sphere(new Lambertian()));
        outer.addSurface(Placement.of(Vec3.ZERO, Vec3.ZERO, v(2, 2, 2)).place(inner));
        moved.addSurface(Placement.of(v(1, 0, 0), Vec3.ZERO, Vec3.ONE).place(outer));
        moved.complete();
        assertEquals(List.of("transforms(2 groups)"), RenderPlan.of(moved).effects());
    }

    @Test
    public void vertexNormalsRunOnlyWithASmoothTriangle() {
        Scene flat = emptyScene();
        flat.addSurface(flatTriangle(new Lambertian()));
        flat.complete();
        assertFalse(RenderPlan.of(flat).runs(Effect.VERTEX_NORMALS));

        Scene smooth = emptyScene();
        smooth.addSurface(flatTriangle(new Lambertian()));
        smooth.addSurface(smoothTriangle(new Lambertian()));
        smooth.addSurface(smoothTriangle(new Lambertian()));
        smooth.complete();
        assertEquals(List.of("vertex normals(2 triangles)"), RenderPlan.of(smooth).effects());
    }

    @Test
    public void primitivesAreTheLeavesOfTheTreeAndEmptyGroupsAreNone() {
        Scene scene = emptyScene();
        Group group = new Group();
        group.addSurface(flatTriangle(null));
        group.addSurface(sphere(null));
        Group empty = new Group();
        group.addSurface(empty.complete());
        scene.addSurface(Placement.of(Vec3.ZERO, v(0, 30, 0), Vec3.ONE).place(group));
        scene.addSurface(sphere(null));
        scene.complete();
        assertEquals(3, RenderPlan.of(scene).primitives());
        assertEquals(0, RenderPlan.of(emptyScene()).primitives());
    }

    @Test
    public void describeListsEffectsWithCountsThenTheSkippedOnes() {
        Scene scene = emptyScene();
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.addLight(new Light(v(0, 1, 3), Vec3.ONE));
        scene.addSurface(sphere(new Phong()));
        scene.complete();
        assertEquals("effects: lighting(1 shader) shadows(2 lights) specular(1 shader);"
                + " skipped: textures, reflection, antialiasing, transforms, vertex normals, bvh", RenderPlan.of(scene).describe());
        assertEquals(List.of("textures", "reflection", "antialiasing", "transforms", "vertex normals", "bvh"), RenderPlan.of(scene).skipped());
    }

    private static Lambertian textured() {
        Lambertian shader = new Lambertian();
        shader.setTexture(new RepeatTexture(new Image(2, 2)));
        return shader;
    }

    @Test
    public void texturedShadersWithALightRunTextures() {
        Scene scene = emptyScene();
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        Lambertian shared = textured();
        scene.addSurface(sphere(shared));
        scene.addSurface(flatTriangle(shared));
        Glazed glazed = new Glazed();
        Phong substrate = new Phong();
        substrate.setTexture(new RepeatTexture(new Image(1, 1)));
        glazed.setSubstrate(substrate);
        scene.addSurface(sphere(glazed));
        scene.addSurface(sphere(new Lambertian()));
        scene.complete();
        RenderPlan plan = RenderPlan.of(scene);
        assertTrue(plan.runs(Effect.TEXTURES));
        // The shared shader counts once; the glaze's substrate counts as its own shader.
        assertTrue(plan.effects().toString(), plan.effects().contains("textures(2 shaders)"));
    }

    @Test
    public void texturesWithoutALightAreSkipped() {
        Scene scene = emptyScene();
        scene.addSurface(sphere(textured()));
        scene.complete();
        RenderPlan plan = RenderPlan.of(scene);
        assertFalse(plan.runs(Effect.TEXTURES));
        assertTrue(plan.skipped().contains("textures"));
    }

    /** A box of 12 triangles is searched through a tree; a mesh of 4 keeps its box and a plain loop. */
    @Test
    public void aBvhIsPlannedWhereItPaysAndDroppedWithoutAcceleration() {
        Scene scene = emptyScene();
        ray.surface.Box box = new ray.surface.Box();
        scene.addSurface(box.complete());
        ray.surface.Mesh small = new ray.surface.Mesh();
        // Two quads: 4 triangles, 8 vertices.
        small.setData(new ray.surface.MeshData(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1},
                null, new int[] {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7}, null));
        scene.addSurface(small.complete());
        scene.complete();
        RenderPlan plan = RenderPlan.of(scene);
        assertTrue(plan.runs(Effect.ACCELERATION));
        assertEquals("bvh(1 mesh, 12 triangles)", plan.effects().get(plan.effects().size() - 1));
        assertTrue(box.hasTree());
        assertFalse(small.hasTree());
        assertEquals("one leaf: the mesh's box, then its 4 triangles", 1, small.treeNodes());
        RenderPlan linear = plan.withAcceleration(ray.accel.Acceleration.NONE);
        assertFalse(linear.runs(Effect.ACCELERATION));
        assertTrue(linear.skipped().contains("bvh"));
        assertEquals("switched back on, the plan is the scene's again", plan.describe(),
                linear.withAcceleration(ray.accel.Acceleration.BVH).describe());
        RenderPlan students = plan.withAcceleration(ray.accel.Acceleration.STUDENT);
        assertEquals("bvh(1 mesh, 12 triangles, your BvhTree)", students.effects().get(students.effects().size() - 1));
    }
}
