package ray.camera;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.math.Vec3;

/** Checks that cameras reject views that have no basis and image planes of non-positive size. */
public class CameraSetupTest {
    @Test
    public void zeroViewDirIsRejected() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewDir(Vec3.ZERO);
        assertCompleteRejects(camera);
    }

    @Test
    public void viewUpParallelToViewDirIsRejected() {
        for (Vec3 up : new Vec3[] {v(0, 0, 2), v(0, 0, -1), Vec3.ZERO}) {
            OrthographicCamera camera = new OrthographicCamera();
            camera.setViewUp(up);
            assertCompleteRejects(camera);
        }
    }

    @Test
    public void nonFiniteViewDirIsRejected() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewDir(v(Double.NaN, 0, -1));
        assertCompleteRejects(camera);
    }

    @Test
    public void nonPositiveSizesAreRejected() {
        for (double bad : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            PerspectiveCamera camera = new PerspectiveCamera();
            assertRejected("viewWidth " + bad, () -> camera.setViewWidth(bad));
            assertRejected("viewHeight " + bad, () -> camera.setViewHeight(bad));
            assertRejected("projDistance " + bad, () -> camera.setProjDistance(bad));
        }
    }

    @Test
    public void viewPointIsKept() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(v(1, 2, 3));
        assertEquals(v(1, 2, 3), camera.getViewPoint());
    }

    private static void assertCompleteRejects(Camera camera) {
        assertRejected("complete()", camera::complete);
    }

    private static void assertRejected(String what, Runnable action) {
        try {
            action.run();
            fail(what + " should throw IllegalArgumentException");
        } catch (IllegalArgumentException expected) {
            // the message says which property is wrong
        }
    }
}
