package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.camera.OrthographicCamera;
import ray.math.Vec3;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.surface.Sphere;
import ray.surface.Triangle;

/**
 * Shadows in a rendered scene: a sphere on the segment from a floor point to a light removes that
 * light, and only that one. Instructor-only: it needs working camera, sphere, triangle and group code.
 */
public class RenderedShadowTest {
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
