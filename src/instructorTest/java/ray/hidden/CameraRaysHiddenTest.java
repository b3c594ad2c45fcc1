package ray.hidden;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotSame;
import static ray.camera.CameraRays.assertRay;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.Ray;
import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.camera.PerspectiveCamera;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden camera cases: a view whose viewDir is not unit length and whose viewUp is not perpendicular
 * to it, at an off-center image point; random cameras against the conventions; and a fresh ray per call.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class CameraRaysHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /**
     * viewDir (3,0,−4) has length 5, and viewUp (3,5,−4) = 5·(0,1,0) + viewDir is not perpendicular
     * to it. w = −viewDir/5 = (−0.6, 0, 0.8). viewUp × w = 5·(0,1,0) × w = 5·(0.8, 0, 0.6) (the
     * viewDir part is parallel to w and drops out), so u = (0.8, 0, 0.6) and v = w × u = (0, 1, 0).
     */
    private static <C extends Camera> C slanted(C camera) {
        camera.setViewPoint(v(1, 2, 3));
        camera.setViewDir(v(3, 0, -4));
        camera.setViewUp(v(3, 5, -4));
        camera.setViewWidth(2);
        camera.setViewHeight(1.5);
        return camera;
    }

    private static final String SLANTED = "camera at (1,2,3) with viewDir (3,0,−4), viewUp (3,5,−4), a 2×1.5 plane";

    @Test
    public void perspectiveWithLongViewDirAndSlantedViewUpAtAnOffCenterPoint() {
        PerspectiveCamera camera = slanted(new PerspectiveCamera());
        camera.setProjDistance(2.5);
        camera.complete();
        // (0.75, 0.2): planeU = 0.25·2 = 0.5, planeV = −0.3·1.5 = −0.45.
        // direction = 0.5·(0.8,0,0.6) − 0.45·(0,1,0) − 2.5·(−0.6,0,0.8) = (0.4 + 1.5, −0.45, 0.3 − 2) = (1.9, −0.45, −1.7).
        assertRay("the perspective " + SLANTED + " at distance 2.5", camera, 0.75, 0.2, v(1, 2, 3), v(1.9, -0.45, -1.7), 1e-13);
    }

    @Test
    public void orthographicWithLongViewDirAndSlantedViewUpAtAnOffCenterPoint() {
        OrthographicCamera camera = slanted(new OrthographicCamera());
        camera.complete();
        // (0.1, 0.9): planeU = −0.4·2 = −0.8, planeV = 0.4·1.5 = 0.6.
        // origin = (1,2,3) − 0.8·(0.8,0,0.6) + 0.6·(0,1,0) = (0.36, 2.6, 2.52); direction −w = (0.6, 0, −0.8).
        assertRay("the orthographic " + SLANTED, camera, 0.1, 0.9, v(0.36, 2.6, 2.52), v(0.6, 0, -0.8), 1e-13);
    }

    /**
     * Random views against the conventions written another way: with g = normalize(viewDir),
     * u = normalize(viewDir × viewUp) (= normalize(viewUp × w), as w = −g) and v = u × g (= w × u),
     * a perspective ray goes along planeU·u + planeV·v + projDistance·g and an orthographic one
     * starts at viewPoint + planeU·u + planeV·v and goes along g.
     */
    @Test
    public void randomViewsFollowTheConventions() {
        Random random = new Random(71);
        for (int i = 0; i < 200; i++) {
            Vec3 eye = randomVec(random, 10);
            Vec3 viewDir = randomVec(random, 5);
            Vec3 viewUp = randomVec(random, 5);
            if (viewDir.normalized().cross(viewUp.normalized()).length() < 0.1) {
                continue; // nearly parallel: the basis would be ill-conditioned
            }
            double width = 0.1 + 4 * random.nextDouble();
            double height = 0.1 + 4 * random.nextDouble();
            double distance = 0.1 + 4 * random.nextDouble();
            Vec3 g = viewDir.normalized();
            Vec3 u = viewDir.cross(viewUp).normalized();
            Vec3 vAxis = u.cross(g);
            double imageU = random.nextDouble();
            double imageV = random.nextDouble();
            double planeU = (imageU - 0.5) * width;
            double planeV = (imageV - 0.5) * height;
            String view = "random view " + i + " (viewPoint " + eye + ", viewDir " + viewDir + ", viewUp " + viewUp
                    + ", " + width + "×" + height + " plane";

            PerspectiveCamera perspective = new PerspectiveCamera();
            setUp(perspective, eye, viewDir, viewUp, width, height);
            perspective.setProjDistance(distance);
            perspective.complete();
            Vec3 direction = u.times(planeU).plus(vAxis.times(planeV)).plus(g.times(distance));
            assertRay("perspective " + view + " at distance " + distance + ")", perspective, imageU, imageV, eye, direction, 1e-12);

            OrthographicCamera orthographic = new OrthographicCamera();
            setUp(orthographic, eye, viewDir, viewUp, width, height);
            orthographic.complete();
            assertRay("orthographic " + view + ")", orthographic, imageU, imageV, eye.plus(u.times(planeU)).plus(vAxis.times(planeV)), g, 1e-12);
        }
    }

    /** The renderer's groups shorten their own copies, but a camera handing out one shared Ray would still be wrong. */
    @Test
    public void everyCallReturnsAFreshFullRay() {
        for (Camera camera : new Camera[] {new PerspectiveCamera(), new OrthographicCamera()}) {
            camera.complete();
            String which = "the default " + camera.getClass().getSimpleName();
            Ray first = camera.generateRay(0.3, 0.6);
            first.start = 0.5;
            first.end = 1;
            Ray second = camera.generateRay(0.3, 0.6);
            assertNotSame(which + ": each call must return a new Ray", first, second);
            assertEquals(which + ": a new ray starts at t = 0", 0, second.start, 0);
            assertEquals(which + ": a new ray never ends", Double.POSITIVE_INFINITY, second.end, 0);
        }
    }

    private static void setUp(Camera camera, Vec3 eye, Vec3 viewDir, Vec3 viewUp, double width, double height) {
        camera.setViewPoint(eye);
        camera.setViewDir(viewDir);
        camera.setViewUp(viewUp);
        camera.setViewWidth(width);
        camera.setViewHeight(height);
    }

    private static Vec3 randomVec(Random random, double extent) {
        return new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1));
    }
}
