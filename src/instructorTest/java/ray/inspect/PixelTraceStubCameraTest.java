package ray.inspect;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.Test;
import ray.Ray;
import ray.camera.PerspectiveCamera;
import ray.math.Vec3;
import ray.scene.Scene;

/**
 * The trace explains a camera that cannot see anything (the handout's stub returns an empty
 * segment) instead of failing, and still reports the background the renderer draws. Uses no
 * student method that matters: whether Group.intersect is the stub or not, nothing is hit.
 */
public class PixelTraceStubCameraTest {

    /** What the handout's PerspectiveCamera.generateRay returns before Task 1: an empty segment. */
    private static final class StubCamera extends PerspectiveCamera {
        @Override
        public Ray generateRay(double imageU, double imageV) {
            return new Ray(viewPoint, w.negate(), 0, 0);
        }
    }

    private static PerspectiveCamera completed(PerspectiveCamera camera) {
        camera.setViewPoint(v(0, 0, 5));
        camera.complete();
        return camera;
    }

    @Test
    public void emptySegmentIsExplainedAsTheTask1Stub() {
        String problem = CameraRayCheck.problem(completed(new PerspectiveCamera()), new Ray(v(0, 0, 5), v(0, 0, -1), 0, 0));
        assertTrue(problem, problem.startsWith("the camera ray's segment is empty (start 0 = end 0)"));
        assertTrue(problem, problem.contains("PerspectiveCamera.generateRay is still the stub? See TODO(Task 1)"));
    }

    @Test
    public void nullRayAndZeroDirectionAreExplained() {
        PerspectiveCamera camera = completed(new PerspectiveCamera());
        String none = CameraRayCheck.problem(camera, null);
        assertTrue(none, none.startsWith("the camera returned no ray (null)"));
        String zero = CameraRayCheck.problem(camera, new Ray(v(0, 0, 5), Vec3.ZERO));
        assertTrue(zero, zero.startsWith("the camera ray's direction is zero"));
    }

    @Test
    public void rayWithANonEmptySegmentHasNoProblem() {
        assertNull(CameraRayCheck.problem(completed(new PerspectiveCamera()), new Ray(v(0, 0, 5), v(0.1, 0, -2))));
    }

    /**
     * A 3×3 view of a wall through the stub camera: the trace says why nothing is hit and gives
     * the background (0.25, 0.5, 0.75) as the 8-bit value: 255·x^(1/2.2) = 135.79, 186.08,
     * 223.74, rounded to 136, 186, 224.
     */
    @Test
    public void traceThroughTheStubCameraExplainsItAndShowsTheBackground() {
        Scene scene = new Scene();
        scene.setCamera(completed(new StubCamera()));
        scene.setImage(3, 3);
        scene.setBackColor(v(0.25, 0.5, 0.75));
        scene.addSurface(new Wall(v(0, 0, 1)));
        scene.complete();
        StringWriter text = new StringWriter();
        int[] rgb;
        try (PrintWriter out = new PrintWriter(text)) {
            rgb = new PixelTrace(scene, "stub.xml", false, 0).run(2, 0, out);
        }
        String out = text.toString();
        assertTrue(out, out.contains("(i, j)       (2, 2)"));
        assertTrue(out, out.contains("! the camera ray's segment is empty (start 0 = end 0), so nothing can be hit:"
                + " StubCamera.generateRay is still the stub? See TODO(Task 1)"));
        assertTrue(out, out.contains("#1 Wall  miss"));
        assertTrue(out, out.contains("none: the pixel shows the background color (0.25, 0.5, 0.75)"));
        assertArrayEquals(new int[] {136, 186, 224}, rgb);
    }
}
