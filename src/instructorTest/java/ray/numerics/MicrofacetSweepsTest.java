package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import org.junit.Test;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;
import ray.shading.BeckmannDistribution;
import ray.shading.BrdfShader;
import ray.shading.Course;

/**
 * The accuracy report's microfacet sweeps: they measure only scenes with a microfacet shader; the
 * scene loaded again for a setting has its microfacet BRDFs replaced and no other; Schlick's factor
 * is R0 head on and 1 at grazing; and the course's rational Beckmann masking term is within 0.32% of
 * the exact erf form over a = 1/(α tanθ) from 1e-4 to 10 (Walter et al. give its error as under 0.35%).
 */
public class MicrofacetSweepsTest {
    private static Scene load(String name) {
        return SceneLoader.load(Path.of("scenes-2019", name + ".xml"), SceneOptions.of(Course.Y2019, null));
    }

    @Test
    public void theSweepsMeasureOnlyScenesWithAMicrofacetShader() {
        assertTrue(load("microfacet-spheres").hasMicrofacetShader());
        assertFalse(load("one-sphere-lambertian").hasMicrofacetShader());
    }

    @Test
    public void aSettingReplacesTheMicrofacetBrdfsAndNoOther() {
        Scene scene = load("microfacet-spheres");
        Scene schlick = scene.reload(o -> o.withBrdfs(b -> MicrofacetApproximations.of(b, MicrofacetApproximations.Change.SCHLICK_FRESNEL)));
        int replaced = 0;
        int kept = 0;
        for (var surface : schlick.getSurfaces().children()) {
            Object brdf = ((BrdfShader) surface.getShader()).brdf();
            if (brdf instanceof MicrofacetApproximations) {
                replaced++;
            } else {
                kept++;
            }
        }
        assertEquals("the four spheres", 4, replaced);
        assertEquals("the floor's Lambertian", 1, kept);
    }

    @Test
    public void schlicksFactorIsR0HeadOnAndOneAtGrazing() {
        assertEquals(0.04, MicrofacetApproximations.schlick(1.5, 1), 1e-15);
        assertEquals(1, MicrofacetApproximations.schlick(1.5, 0), 1e-15);
    }

    @Test
    public void theRationalMaskingTermIsWithinAThirdOfAPercentOfTheErfForm() {
        Vec3 n = new Vec3(0, 0, 1);
        double alpha = 0.5;
        BeckmannDistribution rational = new BeckmannDistribution(alpha);
        double worst = 0;
        for (int k = 1; k <= 2000; k++) {
            double a = 1e-4 * Math.pow(1e5, k / 2000.0); // 1e-4 … 10
            // x at tanθ = 1/(α a), in the xz plane; h along n.
            double tan = 1 / (alpha * a);
            Vec3 x = new Vec3(tan, 0, 1).normalized();
            double exact = MicrofacetApproximations.smithBeckmann(alpha, x, n, n);
            worst = Math.max(worst, Math.abs(rational.masking(x, n, n) - exact) / exact);
        }
        assertTrue("worst relative difference " + worst, worst < 0.0032 && worst > 0.003);
    }
}
