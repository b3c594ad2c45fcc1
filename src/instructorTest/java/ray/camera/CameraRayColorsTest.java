package ray.camera;

import static org.junit.Assert.assertEquals;

import org.junit.Test;
import ray.Ray;
import ray.image.Image;
import ray.math.Vec3;

/**
 * The camera-ray picture ({@code ray1 render --camera-rays}): correct rays of either camera paint
 * red = s / viewWidth + ½, green = t / viewHeight + ½ and no blue; flipped, displaced, sideways
 * and empty rays show as the class comment of {@link CameraRayColors} promises. Uses the solution's
 * cameras, so it is an instructor's test.
 */
public class CameraRayColorsTest {
    private static final double EPS = 1e-12;

    /** A perspective camera at (1, 2, 3) looking along +x, z up, a 4 × 2 plane 3 units away. */
    private static PerspectiveCamera rotatedPerspective() {
        PerspectiveCamera camera = new PerspectiveCamera();
        camera.setViewPoint(new Vec3(1, 2, 3));
        camera.setViewDir(new Vec3(5, 0, 0));
        camera.setViewUp(new Vec3(0, 0, 1));
        camera.setViewWidth(4);
        camera.setViewHeight(2);
        camera.setProjDistance(3);
        camera.complete();
        return camera;
    }

    private static OrthographicCamera rotatedOrthographic() {
        OrthographicCamera camera = new OrthographicCamera();
        camera.setViewPoint(new Vec3(1, 2, 3));
        camera.setViewDir(new Vec3(0, -2, 0));
        camera.setViewUp(new Vec3(0, 0, -1));
        camera.setViewWidth(4);
        camera.setViewHeight(2);
        camera.complete();
        return camera;
    }

    private static void assertColor(Vec3 expected, Vec3 actual) {
        assertEquals("red of " + actual, expected.x, actual.x, EPS);
        assertEquals("green of " + actual, expected.y, actual.y, EPS);
        assertEquals("blue of " + actual, expected.z, actual.z, EPS);
    }

    @Test
    public void correctRaysOfEitherCameraPaintTheirPixelCenters() {
        for (Camera camera : new Camera[] {rotatedPerspective(), rotatedOrthographic()}) {
            // A 4 × 2 image: pixel (i, j) is seen at ((i + ½)/4, (j + ½)/2), which the colors repeat.
            Image image = CameraRayColors.render(camera, 4, 2);
            for (int i = 0; i < 4; i++) {
                for (int j = 0; j < 2; j++) {
                    assertColor(new Vec3((i + 0.5) / 4, (j + 0.5) / 2, 0), image.get(i, j));
                }
            }
        }
    }

    @Test
    public void theDirectionsLengthDoesNotMatter() {
        PerspectiveCamera camera = rotatedPerspective();
        Ray ray = camera.generateRay(0.25, 0.75);
        Ray longer = new Ray(ray.origin, ray.direction.times(7.5));
        assertColor(new Vec3(0.25, 0.75, 0), CameraRayColors.colorOf(camera, longer));
    }

    @Test
    public void aFlippedImageShowsGreenAtTheBottom() {
        OrthographicCamera camera = rotatedOrthographic();
        Ray flipped = camera.generateRay(0.125, 1 - 0.25);
        assertColor(new Vec3(0.125, 0.75, 0), CameraRayColors.colorOf(camera, flipped));
    }

    @Test
    public void raysOffTheirCamerasRuleShowBlue() {
        PerspectiveCamera perspective = rotatedPerspective();
        Ray center = perspective.generateRay(0.5, 0.5);
        // Started 2 units to the side of the eye (the larger view side is 4): blue ½.
        Ray displaced = new Ray(center.origin.plus(perspective.u.times(2)), center.direction);
        assertEquals(0.5, CameraRayColors.colorOf(perspective, displaced).z, EPS);

        OrthographicCamera orthographic = rotatedOrthographic();
        Ray straight = orthographic.generateRay(0.5, 0.5);
        // Tilted 45° toward u: |d/|d| + w| = |(u − w)/√2 + w|... = 2 sin(22.5°).
        Vec3 tilted = straight.direction.normalized().plus(orthographic.u);
        double expected = 2 * Math.sin(Math.PI / 8);
        assertEquals(expected, CameraRayColors.colorOf(orthographic, new Ray(straight.origin, tilted)).z, EPS);
    }

    @Test
    public void raysThatCannotSeeAnythingAreMagenta() {
        PerspectiveCamera camera = rotatedPerspective();
        Vec3 forward = new Vec3(1, 0, 0);
        // The stubs' ray: an empty segment.
        assertColor(CameraRayColors.UNUSABLE, CameraRayColors.colorOf(camera, new Ray(camera.viewPoint, forward, 0, 0)));
        assertColor(CameraRayColors.UNUSABLE, CameraRayColors.colorOf(camera, null));
        assertColor(CameraRayColors.UNUSABLE, CameraRayColors.colorOf(camera, new Ray(camera.viewPoint, forward.negate())));
        assertColor(CameraRayColors.UNUSABLE, CameraRayColors.colorOf(camera, new Ray(camera.viewPoint, new Vec3(0, 1, 0))));
        assertColor(CameraRayColors.UNUSABLE, CameraRayColors.colorOf(camera, new Ray(camera.viewPoint, new Vec3(Double.NaN, 0, 0))));
    }
}
