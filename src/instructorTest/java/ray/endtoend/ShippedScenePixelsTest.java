package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.nio.file.Path;
import org.junit.Test;
import ray.image.Image;
import ray.image.ToneMap;
import ray.math.Vec3;
import ray.scene.Scene;

/**
 * Pixels of shipped scenes whose radiance follows by hand from the scene file: the middle pixel
 * of an odd-sized image looks straight down the view axis, and a corner ray misses everything.
 */
public class ShippedScenePixelsTest {
    private static final int MIDDLE = ShippedScenes.WIDTH / 2;

    /**
     * one-sphere.xml: eye (0,0,5), unit sphere at the origin, so the middle ray hits (0,0,1) with
     * n = (0,0,1). Key light 40 at (3,4,5): to-light (3,4,4), r² = 41, n·l = 4/√41. Fill 6 at
     * (−3,−1,6): to-light (−3,−1,5), r² = 35, n·l = 5/√35. L = kd·(40·4/(41√41) + 6·5/(35√35)).
     */
    @Test
    public void oneSphereMiddlePixelIsLambertUnderTwoLightsAndCornersAreBackground() {
        Scene scene = ShippedScenes.loadSmall(Path.of("scenes/one-sphere.xml"));
        Image image = ShippedScenes.renderSmall(scene);
        double irradiance = 40 * 4 / (41 * Math.sqrt(41)) + 6 * 5 / (35 * Math.sqrt(35));
        Vec3 expected = v(0.2, 0.3, 0.8).times(irradiance);
        assertVec(expected, image.get(MIDDLE, MIDDLE), 1e-12);
        // Blue: x = 0.75435·0.8 = 0.60348, x^(1/2.2) = 0.79494, floor(255·0.79494 + ½) = floor(203.21) = 203.
        assertEquals(203, ToneMap.toByte(image.get(MIDDLE, MIDDLE).z, scene.getExposure()));
        // The corner rays pass the sphere (closest approach 1.64 > 1) and see the black background.
        assertVec(Vec3.ZERO, image.get(0, 0), 0);
        assertVec(Vec3.ZERO, image.get(ShippedScenes.WIDTH - 1, ShippedScenes.WIDTH - 1), 0);
    }

    /**
     * one-sphere-phong.xml: the middle ray hits (0,0,1), n = e = (0,0,1), light 40 at (3,4,5) with
     * n·l = cos θ = 4/√41 and r² = 41. The half vector bisects l and e, so n·h = cos(θ/2) =
     * √((1 + cos θ)/2) and (n·h)^60 = ((1 + cos θ)/2)^30. L = (kd·cos θ + ks·((1 + cos θ)/2)^30)·40/41.
     */
    @Test
    public void phongMiddlePixelHasDiffuseAndHighlightAndCornerShowsBackColor() {
        Scene scene = ShippedScenes.loadSmall(Path.of("scenes/one-sphere-phong.xml"));
        Image image = ShippedScenes.renderSmall(scene);
        double cosTheta = 4 / Math.sqrt(41);
        double specular = Math.pow((1 + cosTheta) / 2, 30);
        Vec3 expected = v(0.75, 0.12, 0.08).times(cosTheta).plus(v(0.8, 0.8, 0.8).times(specular)).times(40.0 / 41);
        assertVec(expected, image.get(MIDDLE, MIDDLE), 1e-12);
        // The upper-left corner misses and shows <backColor>0.1 0.11 0.14</backColor>:
        // floor(255·0.1^(1/2.2) + ½) = floor(255·0.35111 + ½) = 90.
        assertVec(v(0.1, 0.11, 0.14), image.get(0, ShippedScenes.WIDTH - 1), 0);
        assertEquals(90, ToneMap.toByte(image.get(0, ShippedScenes.WIDTH - 1).x, scene.getExposure()));
    }
}
