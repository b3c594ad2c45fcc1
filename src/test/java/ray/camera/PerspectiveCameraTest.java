package ray.camera;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.Ray;
import ray.math.Vec3;

/**
 * Checks PerspectiveCamera.generateRay against rays computed by hand from the conventions:
 * origin = viewPoint, direction = s·u + t·v − projDistance·w with s = (u − ½)·viewWidth and
 * t = (v − ½)·viewHeight, and a segment from 0 to +∞.
 */
public class PerspectiveCameraTest {
    private static final double TOL = 1e-14;

    /** The default camera: basis u = (1,0,0), v = (0,1,0), w = (0,0,1), a 1×1 image plane at distance 1. */
    private static PerspectiveCamera defaultCamera() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.complete();
        return camera;
    }

    /**
     * Looking along +x with +z up: w = (−1,0,0), u = normalize((0,0,1) × w) = (0,−1,0),
     * v = w × u = (0,0,1). With viewWidth 4, viewHeight 2 and projDistance 2 the direction is
     * s·(0,−1,0) + t·(0,0,1) + 2·(1,0,0) = (2, −s, t), s = 4(u − ½), t = 2(v − ½).
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
        assertRay(Vec3.ZERO, v(0, 0, -1), defaultCamera().generateRay(0.5, 0.5));
    }

    @Test
    public void defaultCameraCornerRaysGoThroughImagePlaneCorners() {
        PerspectiveCamera camera = defaultCamera();
        assertRay(Vec3.ZERO, v(-0.5, -0.5, -1), camera.generateRay(0, 0));
        assertRay(Vec3.ZERO, v(0.5, -0.5, -1), camera.generateRay(1, 0));
        assertRay(Vec3.ZERO, v(-0.5, 0.5, -1), camera.generateRay(0, 1));
        assertRay(Vec3.ZERO, v(0.5, 0.5, -1), camera.generateRay(1, 1));
    }

    @Test
    public void rotatedCameraCenterRayIsProjDistanceAlongViewDir() {
        assertRay(v(1, 2, 3), v(2, 0, 0), rotatedCamera().generateRay(0.5, 0.5));
    }

    @Test
    public void rotatedCameraCornerRaysUseItsBasisAndNonSquarePlane() {
        PerspectiveCamera camera = rotatedCamera();
        // (u,v) = (0,0): s = −2, t = −1 → (2, 2, −1); the other corners flip the signs of s and t.
        assertRay(v(1, 2, 3), v(2, 2, -1), camera.generateRay(0, 0));
        assertRay(v(1, 2, 3), v(2, -2, -1), camera.generateRay(1, 0));
        assertRay(v(1, 2, 3), v(2, 2, 1), camera.generateRay(0, 1));
        assertRay(v(1, 2, 3), v(2, -2, 1), camera.generateRay(1, 1));
    }

    @Test
    public void rotatedCameraOffCenterPointDistinguishesUFromV() {
        // (u,v) = (0.25, 0.75): s = 4·(−0.25) = −1, t = 2·0.25 = 0.5 → (2, 1, 0.5).
        assertRay(v(1, 2, 3), v(2, 1, 0.5), rotatedCamera().generateRay(0.25, 0.75));
    }

    @Test
    public void diagonalViewDirIsNormalizedBeforeUse() {
        // viewDir (3,3,0), viewUp (0,0,1): with a = 1/√2, w = (−a,−a,0), u = (a,−a,0), v = (0,0,1).
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewDir(v(3, 3, 0));
        camera.setViewUp(v(0, 0, 1));
        camera.setProjDistance(2);
        camera.complete();
        double a = Math.sqrt(0.5);
        // Center: −2·w = (2a, 2a, 0), of length 2 whatever the length of viewDir.
        assertRay(Vec3.ZERO, v(2 * a, 2 * a, 0), camera.generateRay(0.5, 0.5));
        // (1,1): s = t = ½ → ½(a,−a,0) + ½(0,0,1) + (2a,2a,0) = (2.5a, 1.5a, 0.5).
        assertRay(Vec3.ZERO, v(2.5 * a, 1.5 * a, 0.5), camera.generateRay(1, 1));
    }

    @Test
    public void viewUpNeedNotBePerpendicularToViewDir() {
        // viewUp (0,1,1) with the default viewDir gives the default basis, hence the default rays.
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewUp(v(0, 1, 1));
        camera.complete();
        assertRay(Vec3.ZERO, v(0.5, -0.5, -1), camera.generateRay(1, 0));
        assertRay(Vec3.ZERO, v(-0.5, 0.5, -1), camera.generateRay(0, 1));
    }

    /** Origin and direction as given, and the whole half-line t in (0, ∞). */
    static void assertRay(Vec3 origin, Vec3 direction, Ray ray) {
        assertNotNull("generateRay returned null", ray);
        assertVec("origin", origin, ray.origin, TOL);
        assertVec("direction", direction, ray.direction, TOL);
        assertEquals("start", 0.0, ray.start, 0);
        assertEquals("end", Double.POSITIVE_INFINITY, ray.end, 0);
    }
}
