package ray.camera;

import static ray.camera.CameraRays.assertRay;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks PerspectiveCamera.generateRay against rays computed by hand from the conventions:
 * origin = viewPoint, direction = planeU·u + planeV·v − projDistance·w with the image-plane
 * coordinates planeU = (imageU − ½)·viewWidth and planeV = (imageV − ½)·viewHeight, and a segment
 * from 0 to +∞.
 */
@Points(1)
public class PerspectiveCameraTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final String DEFAULT = "the default PerspectiveCamera (at the origin looking down −z, 1×1 plane at distance 1)";
    private static final String ROTATED = "the PerspectiveCamera at (1,2,3) looking along +x with +z up, 4×2 plane at distance 2";

    /** The default camera: basis u = (1,0,0), v = (0,1,0), w = (0,0,1), a 1×1 image plane at distance 1. */
    private static PerspectiveCamera defaultCamera() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.complete();
        return camera;
    }

    /**
     * Looking along +x with +z up: w = (−1,0,0), u = normalize((0,0,1) × w) = (0,−1,0),
     * v = w × u = (0,0,1). With viewWidth 4, viewHeight 2 and projDistance 2 the direction is
     * planeU·(0,−1,0) + planeV·(0,0,1) + 2·(1,0,0) = (2, −planeU, planeV), planeU = 4(imageU − ½),
     * planeV = 2(imageV − ½).
     */
    private static PerspectiveCamera rotatedCamera() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(v(1, 2, 3));
        camera.setViewDir(v(1, 0, 0));
        camera.setViewUp(v(0, 0, 1));
        camera.setViewWidth(4);
        camera.setViewHeight(2);
        camera.setProjDistance(2);
        camera.complete();
        return camera;
    }

    @Test
    public void defaultCameraCenterRayLooksDownMinusZ() {
        assertRay(DEFAULT, defaultCamera(), 0.5, 0.5, Vec3.ZERO, v(0, 0, -1));
    }

    @Test
    @Points(2)
    public void defaultCameraCornerRaysGoThroughImagePlaneCorners() {
        PerspectiveCamera camera = defaultCamera();
        assertRay(DEFAULT, camera, 0, 0, Vec3.ZERO, v(-0.5, -0.5, -1));
        assertRay(DEFAULT, camera, 1, 0, Vec3.ZERO, v(0.5, -0.5, -1));
        assertRay(DEFAULT, camera, 0, 1, Vec3.ZERO, v(-0.5, 0.5, -1));
        assertRay(DEFAULT, camera, 1, 1, Vec3.ZERO, v(0.5, 0.5, -1));
    }

    @Test
    public void rotatedCameraCenterRayIsProjDistanceAlongViewDir() {
        assertRay(ROTATED, rotatedCamera(), 0.5, 0.5, v(1, 2, 3), v(2, 0, 0));
    }

    @Test
    @Points(2)
    public void rotatedCameraCornerRaysUseItsBasisAndNonSquarePlane() {
        PerspectiveCamera camera = rotatedCamera();
        // (imageU, imageV) = (0,0): planeU = −2, planeV = −1 → (2, 2, −1); the other corners flip their signs.
        assertRay(ROTATED, camera, 0, 0, v(1, 2, 3), v(2, 2, -1));
        assertRay(ROTATED, camera, 1, 0, v(1, 2, 3), v(2, -2, -1));
        assertRay(ROTATED, camera, 0, 1, v(1, 2, 3), v(2, 2, 1));
        assertRay(ROTATED, camera, 1, 1, v(1, 2, 3), v(2, -2, 1));
    }

    @Test
    public void rotatedCameraOffCenterPointDistinguishesUFromV() {
        // (imageU, imageV) = (0.25, 0.75): planeU = 4·(−0.25) = −1, planeV = 2·0.25 = 0.5 → (2, 1, 0.5).
        assertRay(ROTATED, rotatedCamera(), 0.25, 0.75, v(1, 2, 3), v(2, 1, 0.5));
    }

    @Test
    public void diagonalViewDirIsNormalizedBeforeUse() {
        // viewDir (3,3,0), viewUp (0,0,1): with a = 1/√2, w = (−a,−a,0), u = (a,−a,0), v = (0,0,1).
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewDir(v(3, 3, 0));
        camera.setViewUp(v(0, 0, 1));
        camera.setProjDistance(2);
        camera.complete();
        String which = "the PerspectiveCamera at the origin with viewDir (3,3,0), viewUp (0,0,1), projDistance 2";
        double a = Math.sqrt(0.5);
        // Center: −2·w = (2a, 2a, 0), of length 2 whatever the length of viewDir.
        assertRay(which, camera, 0.5, 0.5, Vec3.ZERO, v(2 * a, 2 * a, 0));
        // (1,1): planeU = planeV = ½ → ½(a,−a,0) + ½(0,0,1) + (2a,2a,0) = (2.5a, 1.5a, 0.5).
        assertRay(which, camera, 1, 1, Vec3.ZERO, v(2.5 * a, 1.5 * a, 0.5));
    }

    @Test
    public void viewUpNeedNotBePerpendicularToViewDir() {
        // viewUp (0,1,1) with the default viewDir gives the default basis, hence the default rays.
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewUp(v(0, 1, 1));
        camera.complete();
        String which = "the PerspectiveCamera with viewUp (0,1,1) (its basis is the default one)";
        assertRay(which, camera, 1, 0, Vec3.ZERO, v(0.5, -0.5, -1));
        assertRay(which, camera, 0, 1, Vec3.ZERO, v(-0.5, 0.5, -1));
    }
}
