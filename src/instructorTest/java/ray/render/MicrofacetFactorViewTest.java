package ray.render;

import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import java.util.Random;
import org.junit.Test;
import ray.Ray;
import ray.image.Image;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.scene.SceneException;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;
import ray.shading.Course;
import ray.shading.MicrofacetFactor;
import ray.shading.MicrofacetOracle;

/**
 * The microfacet debug views of ray1's debug scene (scenes-2019/microfacet-debug.xml: a unit
 * Beckmann sphere at the origin, α 0.7, nt 2, k_mf (0.2, 0.3, 0.8), no diffuse part, one light of
 * intensity 11 at (3, 4, 5)): each pixel's radiance is k_mf ⊙ X · I · max(0, n·l)/r² with X the
 * factor, worked out here for seeded pixels from the hit point alone, with the 40-digit oracle's
 * D, F and G1(l)·G1(v) (the scene's numbers as the loader reads them, rounded to float).
 */
public class MicrofacetFactorViewTest {
    private static final Path DEBUG = Path.of("scenes-2019", "microfacet-debug.xml");
    private static final double ALPHA = (float) 0.7;
    private static final double NT = 2;
    private static final Vec3 KMF = new Vec3((float) 0.2, (float) 0.3, (float) 0.8);
    private static final Vec3 LIGHT = new Vec3(3, 4, 5);
    private static final double INTENSITY = 11;

    private static double factor(MicrofacetFactor factor, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 h = l.plus(v).normalized();
        switch (factor) {
            case D:
                return MicrofacetOracle.beckmannD(ALPHA, n, h);
            case F:
                return MicrofacetOracle.fresnel(NT, Math.abs(l.dot(h)));
            default:
                return MicrofacetOracle.beckmannG1(ALPHA, l, n, h) * MicrofacetOracle.beckmannG1(ALPHA, v, n, h);
        }
    }

    @Test
    public void eachViewIsItsFactorTimesTheLight() {
        for (MicrofacetFactor factor : MicrofacetFactor.values()) {
            Scene scene = SceneLoader.load(DEBUG, SceneOptions.of(Course.Y2019, null).withMicrofacetFactor(factor));
            Image image = new Renderer(scene, 0, 0).render().image;
            Random random = new Random(17);
            int checked = 0;
            int lit = 0;
            while (checked < 200) {
                int i = random.nextInt(image.width());
                int j = random.nextInt(image.height());
                Ray ray = scene.getCamera().generateRay((i + 0.5) / image.width(), (j + 0.5) / image.height());
                Vec3 d = ray.direction.normalized();
                // The unit sphere at the origin: |o + t d| = 1, the nearer root.
                double b = ray.origin.dot(d);
                double disc = b * b - (ray.origin.lengthSquared() - 1);
                if (disc <= 0) {
                    continue;
                }
                checked++;
                Vec3 p = ray.origin.plus(d.times(-b - Math.sqrt(disc)));
                Vec3 n = p.normalized();
                Vec3 toLight = LIGHT.minus(p);
                Vec3 l = toLight.normalized();
                double nl = n.dot(l);
                double expected = nl > 0 ? factor(factor, n, l, d.negate()) * INTENSITY * nl / toLight.lengthSquared() : 0;
                lit += nl > 0 && expected > 0 ? 1 : 0;
                Vec3 pixel = image.get(i, j);
                for (int axis = 0; axis < 3; axis++) {
                    double e = KMF.get(axis) * expected;
                    assertTrue(factor + " view, pixel (" + i + ", " + j + "), channel " + axis + ": " + pixel.get(axis) + ", expected " + e,
                            Math.abs(pixel.get(axis) - e) <= 1e-4 * e + 1e-12);
                }
            }
            assertTrue(factor + ": only " + lit + " of the checked pixels are lit", lit > 50);
        }
    }

    @Test
    public void aSceneWithoutAMicrofacetShaderRefusesTheView() {
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(Path.of("scenes-2019", "one-sphere-lambertian.xml"),
                SceneOptions.of(Course.Y2019, null).withMicrofacetFactor(MicrofacetFactor.G)));
        assertTrue(e.getMessage(), e.getMessage().endsWith("a view of the microfacet factor G was asked for, and this scene has no microfacet"
                + " shader (MicrofacetBeckmann, MicrofacetGGX or Microfacet)"));
    }
}
