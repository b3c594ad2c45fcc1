package ray.scene;

import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.Ray;
import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.camera.PerspectiveCamera;
import ray.math.Vec3;

/**
 * Checks that {@code <camera>} elements of both types set every property: the camera's fields are
 * protected, so each test checks the rays it generates at the image center and the four corners.
 * Instructor-only: the rays need working camera code.
 */
public class SceneLoaderCameraTest {
    private static final double TOL = 1e-12;

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    // Both cameras below look along +x with +z up, a basis unlike the default one:
    // w = −normalize(viewDir) = (−1, 0, 0); u = normalize(viewUp × w) = normalize((0, 0, 3) × (−1, 0, 0))
    // = normalize((0, −3, 0)) = (0, −1, 0); v = w × u = (0, 0, 1).
    // With viewWidth 4 and viewHeight 3: planeU = (imageU − ½)·4 ∈ [−2, 2] and planeV = (imageV − ½)·3 ∈ [−1.5, 1.5].

    @Test
    public void perspectiveCameraReadsEveryProperty() {
        Scene scene = SceneFixtures.loadText(folder, """
                <scene>
                  <camera type="PerspectiveCamera">
                    <viewPoint>1 2 3</viewPoint>
                    <viewDir>2 0 0</viewDir>
                    <viewUp>0 0 3</viewUp>
                    <projDistance>2</projDistance>
                    <viewWidth>4</viewWidth>
                    <viewHeight>3</viewHeight>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        Camera camera = scene.getCamera();
        assertTrue("a " + camera, camera instanceof PerspectiveCamera);
        // Every ray starts at viewPoint; direction = planeU·u + planeV·v − projDistance·w = (2, −planeU, planeV).
        assertPerspectiveRay(camera, 0.5, 0.5, v(1, 2, 3), v(2, 0, 0));
        assertPerspectiveRay(camera, 0, 0, v(1, 2, 3), v(2, 2, -1.5));
        assertPerspectiveRay(camera, 1, 0, v(1, 2, 3), v(2, -2, -1.5));
        assertPerspectiveRay(camera, 0, 1, v(1, 2, 3), v(2, 2, 1.5));
        assertPerspectiveRay(camera, 1, 1, v(1, 2, 3), v(2, -2, 1.5));
    }

    @Test
    public void perspectiveCameraWithoutPropertiesUsesTheDefaults() {
        // Defaults: viewPoint 0 0 0, viewDir 0 0 −1, viewUp 0 1 0, projDistance 1, viewWidth = viewHeight = 1,
        // so u = x, v = y, w = z and direction = (imageU − ½, imageV − ½, −1).
        Scene scene = SceneFixtures.loadText(folder, """
                <scene>
                  <camera type="PerspectiveCamera"/>
                  <image>4 3</image>
                </scene>
                """);
        Camera camera = scene.getCamera();
        assertPerspectiveRay(camera, 0.5, 0.5, v(0, 0, 0), v(0, 0, -1));
        assertPerspectiveRay(camera, 0, 0, v(0, 0, 0), v(-0.5, -0.5, -1));
        assertPerspectiveRay(camera, 1, 1, v(0, 0, 0), v(0.5, 0.5, -1));
    }

    @Test
    public void projDistanceAloneScalesOnlyTheForwardPart() {
        Scene scene = SceneFixtures.loadText(folder, """
                <scene>
                  <camera type="PerspectiveCamera">
                    <projDistance>3</projDistance>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        assertPerspectiveRay(scene.getCamera(), 1, 0, v(0, 0, 0), v(0.5, -0.5, -3));
    }

    @Test
    public void orthographicCameraReadsEveryProperty() {
        Scene scene = SceneFixtures.loadText(folder, """
                <scene>
                  <camera type="OrthographicCamera">
                    <viewPoint>1 2 3</viewPoint>
                    <viewDir>2 0 0</viewDir>
                    <viewUp>0 0 3</viewUp>
                    <viewWidth>4</viewWidth>
                    <viewHeight>3</viewHeight>
                  </camera>
                  <image>4 3</image>
                </scene>
                """);
        Camera camera = scene.getCamera();
        assertTrue("a " + camera, camera instanceof OrthographicCamera);
        // origin = viewPoint + planeU·u + planeV·v = (1, 2 − planeU, 3 + planeV); every direction is −w = (1, 0, 0).
        assertOrthographicRay(camera, 0.5, 0.5, v(1, 2, 3), v(1, 0, 0));
        assertOrthographicRay(camera, 0, 0, v(1, 4, 1.5), v(1, 0, 0));
        assertOrthographicRay(camera, 1, 0, v(1, 0, 1.5), v(1, 0, 0));
        assertOrthographicRay(camera, 0, 1, v(1, 4, 4.5), v(1, 0, 0));
        assertOrthographicRay(camera, 1, 1, v(1, 0, 4.5), v(1, 0, 0));
    }

    @Test
    public void orthographicCameraWithoutPropertiesSpansTheUnitSquareAroundTheOrigin() {
        Scene scene = SceneFixtures.loadText(folder, """
                <scene>
                  <camera type="OrthographicCamera"/>
                  <image>4 3</image>
                </scene>
                """);
        assertOrthographicRay(scene.getCamera(), 0, 0, v(-0.5, -0.5, 0), v(0, 0, -1));
        assertOrthographicRay(scene.getCamera(), 1, 1, v(0.5, 0.5, 0), v(0, 0, -1));
    }

    @Test
    public void cameraPropertyNamesMatchIgnoringCase() {
        Scene scene = SceneFixtures.loadText(folder, """
                <SCENE>
                  <Camera type="OrthographicCamera">
                    <VIEWPOINT>1 2 3</VIEWPOINT>
                    <viewwidth>2</viewwidth>
                    <ViewHeight>3</ViewHeight>
                  </Camera>
                  <IMAGE>8 6</IMAGE>
                </SCENE>
                """);
        // viewPoint (1, 2, 3), viewWidth 2, viewHeight 3: the lower-left ray starts at (1 − 1, 2 − 1.5, 3).
        assertOrthographicRay(scene.getCamera(), 0, 0, v(0, 0.5, 3), v(0, 0, -1));
    }

    /** The perspective convention fixes the direction's length too (it is not normalized), so compare it exactly. */
    private static void assertPerspectiveRay(Camera camera, double u, double v, Vec3 origin, Vec3 direction) {
        Ray ray = camera.generateRay(u, v);
        String at = "ray at (" + u + ", " + v + ")";
        assertVec(at + " origin", origin, ray.origin, TOL);
        assertVec(at + " direction", direction, ray.direction, TOL);
    }

    /** An orthographic ray's direction only matters up to length: compare it normalized. */
    private static void assertOrthographicRay(Camera camera, double u, double v, Vec3 origin, Vec3 direction) {
        Ray ray = camera.generateRay(u, v);
        String at = "ray at (" + u + ", " + v + ")";
        assertVec(at + " origin", origin, ray.origin, TOL);
        assertVec(at + " direction", direction, ray.direction.normalized(), TOL);
    }
}
