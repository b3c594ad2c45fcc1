package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.shading.Shader;
import ray.shading.ShadingContext;
import ray.surface.Surface;

/** An exception thrown while rendering (by a shader or a surface) comes out of render() rather than hanging or vanishing. */
public class RenderFailureTest {

    /** Fails on hits in the upper half of the view (y > 0), so some rows succeed and some fail. */
    private static final class FailingShader extends Shader {
        @Override
        public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext shading, int depth) {
            if (hit.location.y > 0) {
                throw new IllegalStateException("shader failed at " + hit.location);
            }
            return Vec3.ONE;
        }
    }

    private static final class FailingSurface extends Surface {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            throw new UnsupportedOperationException("surface failed");
        }
    }

    private static Scene sceneWith(Surface surface) {
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 4, 4), 6, 8);
        scene.addSurface(surface);
        scene.complete();
        return scene;
    }

    private static RuntimeException renderExpectingFailure(Scene scene, int threads) {
        try {
            new Renderer(scene, 1, threads).render();
        } catch (RuntimeException e) {
            return e;
        }
        fail("render() with " + threads + " threads returned although rendering failed");
        return null;
    }

    @Test(timeout = 10_000)
    public void shaderExceptionPropagatesWithOneThread() {
        RuntimeException e = renderExpectingFailure(sceneWith(TestScenes.plane(0, true, new FailingShader())), 1);
        assertEquals(IllegalStateException.class, e.getClass());
        assertEquals(true, e.getMessage().startsWith("shader failed at"));
    }

    @Test(timeout = 10_000)
    public void shaderExceptionPropagatesWithManyThreads() {
        RuntimeException e = renderExpectingFailure(sceneWith(TestScenes.plane(0, true, new FailingShader())), 4);
        assertEquals(IllegalStateException.class, e.getClass());
        assertEquals(true, e.getMessage().startsWith("shader failed at"));
    }

    @Test(timeout = 10_000)
    public void surfaceExceptionPropagatesWithOneAndManyThreads() {
        for (int threads : new int[] {1, 3, 8}) {
            RuntimeException e = renderExpectingFailure(sceneWith(new FailingSurface()), threads);
            assertEquals(UnsupportedOperationException.class, e.getClass());
            assertEquals("surface failed", e.getMessage());
        }
    }
}
