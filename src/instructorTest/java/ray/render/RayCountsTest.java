package ray.render;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Lambertian;
import ray.shading.Light;

/**
 * The renderer's camera-ray counter: n²·W·H camera rays, n = round(√samples), and no other rays when
 * nothing is hit. The counts of shadow and reflection rays, which need hits, are checked in the
 * instructor's SecondaryRayCountsTest.
 */
public class RayCountsTest {

    @Test
    public void cameraRaysAreGridSquaredTimesPixels() {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 5, 3), 5, 3);
        scene.addSurface(TestScenes.plane(0, true, new Lambertian()));
        scene.complete();
        assertEquals(1 * 15, new Renderer(scene, 1, 1).render().rays.camera);
        assertEquals("2 samples round to a 1×1 grid", 15, new Renderer(scene, 2, 1).render().rays.camera);
        assertEquals("3 samples round to a 2×2 grid", 4 * 15, new Renderer(scene, 3, 1).render().rays.camera);
        assertEquals(9 * 15, new Renderer(scene, 9, 4).render().rays.camera);
    }

    @Test
    public void backgroundSamplesTraceNoShadowRays() {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 5, 3), 5, 3);
        scene.addLight(new Light(v(0, 0, 3), Vec3.ONE));
        scene.complete();
        RenderResult result = new Renderer(scene, 1, 1).render();
        assertEquals(15, result.rays.camera);
        assertEquals(0, result.rays.shadow);
        assertEquals(0, result.rays.reflection);
    }
}
