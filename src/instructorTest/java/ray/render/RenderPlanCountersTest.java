package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Collectors;
import org.junit.Test;
import ray.accel.Acceleration;
import ray.image.Image;
import ray.math.Vec3;
import ray.shading.Effect;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;
import ray.shading.Glazed;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.Phong;
import ray.shading.RGBNormals;
import ray.shading.Shader;
import ray.shading.Texture;
import ray.surface.Box;
import ray.surface.Triangle;

/**
 * The render plan proved by the counters: an effect the plan skips costs no ray and no evaluation
 * (no lights → no shadow rays, Lambertian only → no specular term, no Glazed → no reflection ray),
 * N samples trace exactly n²·W·H camera rays, intersection tests are rays × primitives, every
 * shipped scene's plan is what its file holds, and skipping zero-contribution work leaves the image
 * bit for bit the same as a render that does all of it. Instructor-only: it needs hits, so working
 * camera, sphere, triangle and group code.
 */
public class RenderPlanCountersTest {

    /** A 5×3 orthographic view straight down onto a plane at z = 0 that fills it: every camera ray hits. */
    private static Scene floorScene(Shader shader) {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 5, 3), 5, 3);
        scene.addSurface(TestScenes.plane(0, true, shader));
        return scene;
    }

    @Test
    public void noLightsTraceNoShadowRaysAndRunNoLighting() {
        Scene scene = floorScene(new Phong());
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 2).render();
        assertTrue(result.plan.skipped().containsAll(List.of("lighting", "shadows")));
        assertEquals(15, result.rays.camera);
        assertEquals(0, result.rays.shadow);
        assertEquals("no light, no specular term to evaluate", 0, result.rays.specular);
    }

    @Test
    public void lambertianOnlyEvaluatesNoSpecularTerm() {
        Scene scene = floorScene(new Lambertian());
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.addLight(new Light(v(2, 0, 3), Vec3.ONE));
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 2).render();
        assertEquals(0, result.rays.specular);
        // Both lights are above the floor, so each of the 15 hits traces 2 shadow rays.
        assertEquals(30, result.rays.shadow);
    }

    @Test
    public void phongEvaluatesOneSpecularTermPerLightPerHit() {
        Scene scene = floorScene(new Phong());
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.addLight(new Light(v(2, 0, 3), Vec3.ONE));
        scene.complete();
        RenderResult result = new Renderer(scene, 4, 2).render();
        // 2×2 grid: 4·15 = 60 hits, 2 lights each.
        assertEquals(120, result.rays.specular);
    }

    @Test
    public void noGlazedShaderTracesNoReflectionRays() {
        Scene scene = floorScene(new Phong());
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 1).render();
        assertTrue(result.plan.skipped().contains("reflection"));
        assertEquals(0, result.rays.reflection);
    }

    @Test
    public void nSamplesTraceExactlyGridSquaredTimesPixelsCameraRays() {
        Scene scene = floorScene(new Lambertian());
        scene.complete();
        int[] samples = {1, 2, 3, 4, 7, 9, 16};
        int[] side = {1, 1, 2, 2, 3, 3, 4}; // round(√N)
        for (int k = 0; k < samples.length; k++) {
            RenderResult result = new Renderer(scene, samples[k], 3).render();
            assertEquals("N = " + samples[k], (long) side[k] * side[k] * 5 * 3, result.rays.camera);
            assertEquals(side[k] > 1, result.plan.runs(Effect.ANTIALIASING));
        }
    }

    /**
     * The light loop is the students' code, and the counters count what it does: a loop that asks
     * the shadow test before it knows the light is behind the surface shows one shadow ray per light
     * and hit where the solution's casts none; the image is the same.
     */
    @Test
    public void theCountersShowAShadowRayTheLightLoopDidNotNeed() {
        Lambertian shadowTestFirst = new Lambertian() {
            @Override
            public Vec3 shade(ray.IntersectionRecord hit, ray.Ray ray, ray.shading.ShadingContext context, int depth) {
                Vec3 sum = Vec3.ZERO;
                for (Light light : context.lights()) {
                    if (context.unoccluded(hit, light.getPosition())) {
                        Vec3 toLight = light.getPosition().minus(hit.location);
                        double cosine = Math.max(0, hit.normal.dot(toLight.normalized()));
                        sum = sum.plus(diffuseColorAt(hit).times(light.getIntensity()).times(cosine / toLight.lengthSquared()));
                    }
                }
                return sum;
            }
        };
        RenderResult[] results = new RenderResult[2];
        Shader[] shaders = {new Lambertian(), shadowTestFirst};
        for (int k = 0; k < 2; k++) {
            Scene scene = floorScene(shaders[k]);
            scene.addLight(new Light(v(0, 0, -3), Vec3.ONE)); // below the floor, which faces up
            scene.complete();
            results[k] = new Renderer(scene, 1, 2).render();
        }
        assertEquals("the solution's loop: no shadow ray for a light behind the surface", 0, results[0].rays.shadow);
        assertEquals("a loop that tests shadows first: one per hit", 15, results[1].rays.shadow);
        assertSameBits("the same image", results[0].image, results[1].image);
    }

    @Test
    public void withoutAccelerationIntersectionTestsAreRaysTimesPrimitives() {
        Scene scene = floorScene(new Lambertian());
        // Two more triangles far off to the side: hit by nothing, tested by every ray.
        scene.addSurface(TestScenes.plane(-100, true, new Lambertian()));
        scene.addSurface(TestScenes.plane(-200, true, new Lambertian()));
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.complete();
        RenderResult result = new Renderer(RenderPlan.of(scene, 1).withAcceleration(Acceleration.NONE), 2).render();
        assertEquals(3, result.plan.primitives());
        // 15 camera rays + 15 shadow rays, each tested against 3 triangles, and no box tested.
        assertEquals(15, result.rays.shadow);
        assertEquals(List.of(45L, 45L, 0L), counts(result.rays.intersectionTests));
        assertEquals(0, result.rays.totalBoxTests());
    }

    /**
     * The floor (first in the file), then a wall between it and the light (second; out of the
     * orthographic camera's view), then a triangle far below. A shadow ray's search stops at the wall:
     * 2 tests where the closest-hit search makes 3; camera rays test all 3 either way (the student's
     * linear loop).
     */
    @Test
    public void shadowRaysStopAtTheFirstBlocker() {
        Scene scene = floorScene(new Lambertian());
        Triangle wall = new Triangle(v(50, -40, -10), v(50, 40, -10), v(50, 0, 10));
        wall.setShader(new Lambertian());
        scene.addSurface(wall.complete());
        scene.addSurface(TestScenes.plane(-100, true, new Lambertian()));
        scene.addLight(new Light(v(100, 0, 3), Vec3.ONE));
        scene.complete();
        RenderResult fast = new Renderer(RenderPlan.of(scene, 1), 2).render();
        RenderResult linear = new Renderer(RenderPlan.of(scene, 1).withAcceleration(Acceleration.NONE), 2).render();
        assertEquals(15, fast.rays.shadow);
        assertEquals(List.of(45L, 30L, 0L), counts(fast.rays.intersectionTests));
        assertEquals(List.of(45L, 45L, 0L), counts(linear.rays.intersectionTests));
        assertSameBits("any-hit vs closest-hit shadows", linear.image, fast.image);
    }

    /** A box of 12 triangles searched through its hierarchy: every box test and triangle test counted. */
    @Test
    public void aBoxCountsItsNodesAndTriangleTests() {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 5, 3), 5, 3);
        Box box = new Box();
        box.setMinPt(v(-10, -10, -1));
        box.setMaxPt(v(10, 10, 0));
        box.setShader(new Lambertian());
        scene.addSurface(box.complete());
        scene.complete();
        RenderResult fast = new Renderer(RenderPlan.of(scene, 1), 1).render();
        RenderResult linear = new Renderer(RenderPlan.of(scene, 1).withAcceleration(Acceleration.NONE), 1).render();
        assertTrue(fast.plan.runs(Effect.ACCELERATION));
        assertEquals("bvh(1 mesh, 12 triangles)", fast.plan.effects().get(fast.plan.effects().size() - 1));
        assertEquals(List.of(15L * 12, 0L, 0L), counts(linear.rays.intersectionTests));
        long tests = fast.rays.intersectionTests[0];
        // Each ray straight down onto the top face enters at least the root and a leaf, and tests at
        // least the top face's triangle that it hits, but far fewer than all 12.
        assertTrue("tests " + tests, tests >= 15 && tests <= 15 * 6);
        assertTrue("boxes " + fast.rays.boxTests[0], fast.rays.boxTests[0] >= 15 * 2);
        assertSameBits("bvh vs linear", linear.image, fast.image);
    }

    private static List<Long> counts(long[] byKind) {
        return java.util.Arrays.stream(byKind).boxed().collect(Collectors.toList());
    }

    /** The effects each shipped scene's file calls for (from its lights, shaders, samples, groups and meshes). */
    private static final Map<String, Set<Effect>> SHIPPED = new TreeMap<>(Map.ofEntries(
            Map.entry("antialiased", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.ANTIALIASING, Effect.TRANSFORMS)),
            Map.entry("glazed-sphere", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.REFLECTION, Effect.TRANSFORMS)),
            Map.entry("group-transforms", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TRANSFORMS, Effect.VERTEX_NORMALS)),
            Map.entry("mesh-flat", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TRANSFORMS)),
            Map.entry("mesh-smooth", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TRANSFORMS, Effect.VERTEX_NORMALS)),
            Map.entry("meshes-and-boxes", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TRANSFORMS, Effect.VERTEX_NORMALS)),
            Map.entry("one-sphere-phong", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR)),
            Map.entry("one-sphere", Set.of(Effect.LIGHTING, Effect.SHADOWS)),
            Map.entry("lights-and-shadows", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR)),
            Map.entry("phong-highlights", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR)),
            Map.entry("mirror-pair", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.REFLECTION)),
            Map.entry("rgb-normals", Set.of(Effect.ACCELERATION)),
            Map.entry("two-boxes", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS)),
            Map.entry("inverted-box", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS)),
            Map.entry("wire-box-ortho", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR)),
            Map.entry("wire-box", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR)),
            Map.entry("far-from-origin", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.REFLECTION, Effect.TRANSFORMS)),
            Map.entry("far-tiny-sphere", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR)),
            Map.entry("huge-ground-sphere", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR)),
            Map.entry("inside-closed-mesh", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.TRANSFORMS)),
            Map.entry("cylinder", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TRANSFORMS)),
            Map.entry("globe", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TEXTURES)),
            Map.entry("eclipse", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TEXTURES)),
            Map.entry("tablecloth", Set.of(Effect.ACCELERATION, Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TEXTURES, Effect.TRANSFORMS,
                    Effect.VERTEX_NORMALS)),
            Map.entry("diagnostic", Set.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.TEXTURES, Effect.TRANSFORMS))));

    private static List<Path> shippedScenes() {
        return SceneFiles.under(Path.of("scenes"));
    }

    /** The scene at 24×18 pixels (its own samples), so that every shipped scene renders in a blink. */
    private static Scene loadSmall(Path file) {
        Scene scene = SceneLoader.load(file);
        scene.setImage(24, 18);
        return scene;
    }

    @Test
    public void everyShippedScenePlansWhatItsFileHoldsAndTheCountersAgree() throws IOException {
        List<Path> files = shippedScenes();
        assertEquals("a new shipped scene needs its row in SHIPPED", SHIPPED.keySet(),
                files.stream().map(SceneFiles::nameOf).collect(Collectors.toCollection(java.util.TreeSet::new)));
        for (Path file : files) {
            String name = SceneFiles.nameOf(file);
            Scene scene = loadSmall(file);
            RenderResult result = new Renderer(scene, 0, 2).render();
            RenderPlan plan = result.plan;
            for (Effect effect : Effect.values()) {
                assertEquals(name + " " + effect, SHIPPED.get(name).contains(effect), plan.runs(effect));
            }
            int n = plan.gridSide();
            assertEquals(name, (long) n * n * 24 * 18, result.rays.camera);
            // A skipped effect costs nothing; at 24×18 every running one is still exercised.
            assertEquals(name, plan.runs(Effect.SHADOWS), result.rays.shadow > 0);
            assertEquals(name, plan.runs(Effect.SPECULAR), result.rays.specular > 0);
            assertEquals(name, plan.runs(Effect.REFLECTION), result.rays.reflection > 0);
            assertEquals(name, plan.runs(Effect.TEXTURES), result.rays.textureLookups > 0);
            // Without acceleration the counted tests are exactly rays × primitives; with it, fewer or as many.
            RenderResult linear = new Renderer(plan.withAcceleration(Acceleration.NONE), 2).render();
            assertEquals(name, result.rays.total() * plan.primitives(), linear.rays.totalIntersectionTests());
            assertEquals(name, 0, linear.rays.totalBoxTests());
            assertTrue(name, result.rays.totalIntersectionTests() <= linear.rays.totalIntersectionTests());
            assertEquals(name, plan.runs(Effect.ACCELERATION) || plan.runs(Effect.TRANSFORMS), result.rays.totalBoxTests() > 0);
        }
    }

    private static void assertSameBits(String what, Image expected, Image actual) {
        for (int j = 0; j < expected.height(); j++) {
            for (int i = 0; i < expected.width(); i++) {
                Vec3 e = expected.get(i, j);
                Vec3 a = actual.get(i, j);
                String at = what + " pixel (" + i + ", " + j + ")";
                assertEquals(at, Double.doubleToRawLongBits(e.x), Double.doubleToRawLongBits(a.x));
                assertEquals(at, Double.doubleToRawLongBits(e.y), Double.doubleToRawLongBits(a.y));
                assertEquals(at, Double.doubleToRawLongBits(e.z), Double.doubleToRawLongBits(a.z));
            }
        }
    }

    @Test
    public void workThatCannotChangeThePixelIsSkippedAndTheImageIsTheSame() {
        // A glaze of index 1 has R0 = 0, and seen straight down (cos θ = 1) R = 0: no reflection ray is
        // needed. A light under the floor adds nothing (n·l < 0 for Lambertian): no shadow ray is needed.
        // So the glazed floor lit from above and below must render bit for bit as the glaze's
        // substrate lit from above alone, with the same rays.
        Glazed glazed = new Glazed();
        glazed.setRefractiveIndex(1);
        Scene both = floorScene(glazed);
        both.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        both.addLight(new Light(v(0, 0, -3), Vec3.ONE));
        both.complete();
        Scene above = floorScene(glazed.getSubstrate());
        above.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        above.complete();
        RenderResult skipping = new Renderer(both, 1, 2).render();
        RenderResult plain = new Renderer(above, 1, 2).render();
        assertSameBits("floor", plain.image, skipping.image);
        assertEquals("one shadow ray per hit, for the light above", 15, skipping.rays.shadow);
        assertEquals(plain.rays.shadow, skipping.rays.shadow);
        assertEquals(0, skipping.rays.reflection);
    }

    @Test
    public void rgbNormalsSceneNeedsNoLightEvenWithLights() {
        Scene scene = floorScene(new RGBNormals());
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 1).render();
        assertEquals(List.of(), result.plan.effects());
        assertEquals(0, result.rays.shadow);
    }

    /** A texture of one texel that counts its lookups (from every render thread). */
    private static final class CountingTexture extends Texture {
        final AtomicLong lookups = new AtomicLong();

        CountingTexture() {
            super(new Image(1, 1));
        }

        @Override
        public Vec3 getTexColor(double u, double v) {
            lookups.incrementAndGet();
            return image.get(0, 0);
        }
    }

    @Test
    public void aTextureIsLookedUpOncePerLitHitAndNeverWithoutALight() {
        CountingTexture texture = new CountingTexture();
        Lambertian shader = new Lambertian();
        shader.setTexture(texture);
        Scene dark = floorScene(shader);
        dark.complete();
        RenderResult unlit = new Renderer(dark, 4, 2).render();
        assertEquals("no light, no lookup", 0, texture.lookups.get());
        assertEquals(0, unlit.rays.textureLookups);
        assertTrue(unlit.plan.skipped().contains("textures"));

        Scene lit = floorScene(shader);
        lit.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        lit.addLight(new Light(v(2, 0, 3), Vec3.ONE));
        lit.complete();
        RenderResult result = new Renderer(lit, 4, 2).render();
        // 2×2 grid: 60 hits, one lookup each whatever the number of lights; the counter agrees with the texture.
        assertEquals(60, texture.lookups.get());
        assertEquals(60, result.rays.textureLookups);
    }
}
