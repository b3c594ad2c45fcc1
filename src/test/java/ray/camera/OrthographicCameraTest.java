package ray.camera;

import static ray.camera.CameraRays.assertRay;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks OrthographicCamera.generateRay against rays computed by hand from the conventions:
 * origin = viewPoint + planeU·u + planeV·v, direction = −w, with the image-plane coordinates
 * planeU = (imageU − ½)·viewWidth and planeV = (imageV − ½)·viewHeight, and a segment from 0 to +∞.
 */
@Points(1)
public class OrthographicCameraTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final String DEFAULT = "the default OrthographicCamera (at the origin looking down −z, 1×1 plane)";
    private static final String ROTATED = "the OrthographicCamera at (1,2,3) looking along +x with +z up, 4×2 plane";

    private static OrthographicCamera defaultCamera() {
        OrthographicCamera camera = new OrthographicCamera();
        camera.complete();
        return camera;
    }

    /**
     * Looking along +x with +z up from (1,2,3): u = (0,−1,0), v = (0,0,1), −w = (1,0,0).
     * With viewWidth 4 and viewHeight 2 the origin is (1, 2 − planeU, 3 + planeV), planeU = 4(imageU − ½),
     * planeV = 2(imageV − ½).
     */
    private static OrthographicCamera rotatedCamera() {
        OrthographicCamera camera = new OrthographicCamera();
        camera.setViewPoint(v(1, 2, 3));
        camera.setViewDir(v(1, 0, 0));
        camera.setViewUp(v(0, 0, 1));
        camera.setViewWidth(4);
        camera.setViewHeight(2);
        camera.complete();
        return camera;
    }

    @Test
    public void defaultCameraCenterRayStartsAtViewPoint() {
        assertRay(DEFAULT, defaultCamera(), 0.5, 0.5, v(0, 0, 0), v(0, 0, -1));
    }

    @Test
    @Points(2)
    public void defaultCameraCornerRaysAreParallelAndStartOnTheImagePlaneCorners() {
        OrthographicCamera camera = defaultCamera();
        assertRay(DEFAULT, camera, 0, 0, v(-0.5, -0.5, 0), v(0, 0, -1));
        assertRay(DEFAULT, camera, 1, 0, v(0.5, -0.5, 0), v(0, 0, -1));
        assertRay(DEFAULT, camera, 0, 1, v(-0.5, 0.5, 0), v(0, 0, -1));
        assertRay(DEFAULT, camera, 1, 1, v(0.5, 0.5, 0), v(0, 0, -1));
    }

    @Test
    public void rotatedCameraCenterRayStartsAtViewPoint() {
        assertRay(ROTATED, rotatedCamera(), 0.5, 0.5, v(1, 2, 3), v(1, 0, 0));
    }

    @Test
    @Points(2)
    public void rotatedCameraCornerRaysUseItsBasisAndNonSquarePlane() {
        OrthographicCamera camera = rotatedCamera();
        // (0,0): planeU = −2, planeV = −1 → (1, 4, 2); the other corners flip their signs.
        assertRay(ROTATED, camera, 0, 0, v(1, 4, 2), v(1, 0, 0));
        assertRay(ROTATED, camera, 1, 0, v(1, 0, 2), v(1, 0, 0));
        assertRay(ROTATED, camera, 0, 1, v(1, 4, 4), v(1, 0, 0));
        assertRay(ROTATED, camera, 1, 1, v(1, 0, 4), v(1, 0, 0));
    }

    @Test
    public void rotatedCameraOffCenterPointDistinguishesUFromV() {
        // (0.25, 0.75): planeU = −1, planeV = 0.5 → origin (1, 3, 3.5).
        assertRay(ROTATED, rotatedCamera(), 0.25, 0.75, v(1, 3, 3.5), v(1, 0, 0));
    }

    @Test
    public void directionIsAlongViewDirWhateverItsLength() {
        OrthographicCamera camera = new OrthographicCamera();
        camera.setViewDir(v(0, -5, 0));
        camera.setViewUp(v(0, 0, -1));
        camera.complete();
        // w = (0,1,0), u = normalize((0,0,−1) × (0,1,0)) = (1,0,0), v = w × u = (0,0,−1).
        assertRay("the OrthographicCamera with viewDir (0,−5,0), viewUp (0,0,−1): direction −w = (0,−1,0)",
                camera, 1, 0, v(0.5, 0, 0.5), v(0, -1, 0));
    }
}
