package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.camera.OrthographicCamera;
import ray.math.Vec3;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.surface.Sphere;
import ray.surface.Triangle;

/**
 * Shadows: a blocked light adds nothing, and a light that could add nothing anyway
 * (behind a Lambertian surface) costs no shadow ray.
 */
public class ShadowTest {
    private static final double TOL = 1e-12;

    private final IntersectionRecord hit = FakeTracer.hit(Vec3.ZERO, v(0, 0, 1));
    private final Ray eyeRay = FakeTracer.rayFrom(v(0, 0, 5), Vec3.ZERO);

    @Test
    public void blockedLightAddsNothingWhileOtherLightsStillCount() {
        Vec3 blocked = v(0, 0, 2);
        FakeTracer tracer = new FakeTracer()
                .light(blocked, v(4, 4, 4))
                .light(v(3, 0, 4), v(25, 25, 25));
        tracer.lit = position -> !position.equals(blocked);
        Vec3 L = new Lambertian().shade(hit, eyeRay, tracer, 0);
        // Only the second light: 25·0.8/25
        assertVec(v(0.8, 0.8, 0.8), L, TOL);
        assertEquals(2, tracer.shadowRays);
    }

    @Test
    public void lightBehindLambertianCostsNoShadowRay() {
        FakeTracer tracer = new FakeTracer()
                .light(v(0, 0, -2), v(4, 4, 4))
                .light(v(5, 5, -0.001), v(4, 4, 4));
        assertVec(Vec3.ZERO, new Lambertian().shade(hit, eyeRay, tracer, 0), 0);
        assertEquals(0, tracer.shadowRays);
    }

    @Test
    public void blackDiffuseColorCostsNoShadowRay() {
        FakeTracer tracer = new FakeTracer().light(v(0, 0, 2), v(4, 4, 4));
        assertVec(Vec3.ZERO, new Lambertian(Vec3.ZERO).shade(hit, eyeRay, tracer, 0), 0);
        assertEquals(0, tracer.shadowRays);
    }

    /**
     * One pixel looking straight down at a floor at z = 0 through the point (0, 0, 0); a light at
     * (4, 0, 4) (n·l = 1/√2, r² = 32, I = 32: L = 1/√2), and optionally a sphere at (2, 0, 2),
     * radius 0.5, on the segment to the light but 2 away from the camera ray.
     */
    private static RenderResult renderFloor(boolean withBlocker, boolean withSecondLight) {
        OrthographicCamera camera = new OrthographicCamera();
        camera.setViewPoint(v(0, 0, 5));
        camera.setViewWidth(0.01);
        camera.setViewHeight(0.01);
        camera.complete();
        Scene scene = new Scene();
        scene.setCamera(camera);
        scene.setImage(1, 1);
        scene.addLight(new Light(v(4, 0, 4), v(32, 32, 32)));
        if (withSecondLight) {
            // Straight above: n·l = 1, r² = 9, I = 9: adds 1.
            scene.addLight(new Light(v(0, 0, 3), v(9, 9, 9)));
        }
        scene.addSurface(new Triangle(v(-20, -20, 0), v(20, -20, 0), v(0, 20, 0)).complete());
        if (withBlocker) {
            scene.addSurface(new Sphere(v(2, 0, 2), 0.5).complete());
        }
        scene.complete();
        return new Renderer(scene, 1, 1).render();
    }

    @Test
    public void unblockedFloorIsLitByTheLight() {
        RenderResult result = renderFloor(false, false);
        double expected = 1 / Math.sqrt(2);
        assertVec(v(expected, expected, expected), result.image.get(0, 0), 1e-9);
        assertEquals(1, result.rays.shadow);
    }

    @Test
    public void sphereOnTheSegmentToTheLightCastsAShadow() {
        RenderResult result = renderFloor(true, false);
        assertVec(Vec3.ZERO, result.image.get(0, 0), 0);
        assertEquals(1, result.rays.shadow);
    }

    @Test
    public void shadowRemovesOnlyTheBlockedLight() {
        RenderResult result = renderFloor(true, true);
        assertVec(v(1, 1, 1), result.image.get(0, 0), 1e-9);
        assertEquals(2, result.rays.shadow);
    }
}
