package ray.render;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Glazed;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.RGBNormals;
import ray.shading.Shader;

/**
 * The renderer's counters of the rays that follow a hit: one shadow ray per contributing light, one
 * reflection ray per glazed hit, bounded by Glazed.MAX_DEPTH. Instructor-only: it needs hits, so
 * working camera, triangle and group code.
 */
public class SecondaryRayCountsTest {

    /** A 5×3 view straight down onto a plane at z = 0 that fills it. */
    private static Scene floorScene(Shader shader) {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 5, 3), 5, 3);
        scene.addSurface(TestScenes.plane(0, true, shader));
        return scene;
    }

    @Test
    public void withoutLightsNoShadowRaysAreTraced() {
        Scene scene = floorScene(new Lambertian());
        scene.complete();
        RenderResult result = new Renderer(scene, 4, 2).render();
        assertEquals(4 * 5 * 3, result.rays.camera);
        assertEquals(0, result.rays.shadow);
        assertEquals(0, result.rays.reflection);
        assertEquals(60, result.rays.total());
    }

    @Test
    public void eachHitTracesOneShadowRayPerLightInFront() {
        Scene scene = floorScene(new Lambertian());
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.addLight(new Light(v(2, 1, 4), Vec3.ONE));
        scene.addLight(new Light(v(0, 0, -3), Vec3.ONE)); // below the floor: no contribution, no shadow ray
        scene.complete();
        RenderResult result = new Renderer(scene, 4, 2).render();
        assertEquals(60, result.rays.camera);
        assertEquals(2 * 60, result.rays.shadow);
    }

    @Test
    public void glazedFloorTracesOneReflectionRayPerCameraRay() {
        Scene scene = floorScene(new Glazed());
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 1).render();
        assertEquals(15, result.rays.camera);
        assertEquals("each reflection goes up into the empty sky", 15, result.rays.reflection);
        assertEquals(30, result.rays.total());
    }

    @Test
    public void facingMirrorsBounceUntilMaxDepth() {
        // A camera at z = 0 looks down at a glaze facing up at z = −1; a glaze facing down at z = +1
        // sends every reflection back. Each camera ray reflects MAX_DEPTH times, then stops.
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 0), 2, 2), 2, 2);
        Glazed below = new Glazed();
        below.setSubstrate(new RGBNormals());
        Glazed above = new Glazed();
        above.setSubstrate(new RGBNormals());
        scene.addSurface(TestScenes.plane(-1, true, below));
        scene.addSurface(TestScenes.plane(1, false, above));
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 1).render();
        assertEquals(4, result.rays.camera);
        assertEquals(4 * Glazed.MAX_DEPTH, result.rays.reflection);

        // Head-on, R = 0.04 at every bounce. Bounce k (k = 0..12) sees the lower glaze (RGBNormals
        // (0.5, 0.5, 1)) for even k and the upper one ((0.5, 0.5, 0)) for odd k, weighted 0.04^k·0.96:
        // red = 0.48·Σ 0.04^k = 0.5·(1 − 0.04^13); blue = 0.96·Σ 0.0016^m (m = 0..6) ≈ 0.96/0.9984.
        assertVec(v(0.5, 0.5, 0.96 / 0.9984), result.image.get(1, 0), 1e-12);
    }
}
