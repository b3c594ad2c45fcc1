package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Blinn–Phong, L = Σ (kd ⊙ I · max(0, n·l) + ks ⊙ I · max(0, n·h)^p) / r² with h = normalize(l + e),
 * including the course's convention that the specular term is not gated by n·l. Instructor-only: it also
 * pins the solution's shadow rays (none for a light that adds nothing), which the render counters
 * rely on and students may do otherwise; their tests are ray.shading.PhongTest and the hidden ones.
 */
public class PhongSolutionTest {
    private static final double TOL = 1e-12;

    private final IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, 1));

    private static Phong phong(Vec3 kd, Vec3 ks, double exponent) {
        Phong p = new Phong();
        p.setDiffuseColor(kd);
        p.setSpecularColor(ks);
        p.setExponent(exponent);
        return p;
    }

    @Test
    public void diffusePlusSpecularWithHalfVector() {
        // l = (0, 0, 1), e = (3, 0, 4)/5 = (0.6, 0, 0.8); l + e = (0.6, 0, 1.8), |l + e|² = 3.6,
        // n·h = 1.8/√3.6 = 3/√10, so (n·h)² = 0.9. r² = 4 and I = 4, so I/r² = 1.
        Ray ray = FakeShadingContext.rayFrom(v(3, 0, 4), Vec3.ZERO);
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 2), v(4, 4, 4));
        Vec3 L = phong(v(0.5, 0.5, 0.5), v(1, 0.5, 0), 2).shade(hit, ray, shading, 0);
        assertVec(v(0.5 + 0.9, 0.5 + 0.45, 0.5), L, TOL);
    }

    @Test
    public void exponentSharpensTheHighlight() {
        // Same geometry: n·h = 3/√10, (n·h)^4 = 0.81; kd = 0 isolates the specular term.
        Ray ray = FakeShadingContext.rayFrom(v(3, 0, 4), Vec3.ZERO);
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 2), v(4, 4, 4));
        assertVec(v(0.81, 0.81, 0.81), phong(Vec3.ZERO, Vec3.ONE, 4).shade(hit, ray, shading, 0), TOL);
        // Exponent 1 gives n·h itself.
        assertVec(v(1, 1, 1).times(3 / Math.sqrt(10)), phong(Vec3.ZERO, Vec3.ONE, 1).shade(hit, ray, shading, 0), TOL);
    }

    @Test
    public void mirrorConfigurationGivesFullSpecular() {
        // Eye and light symmetric about the normal: h = n, so the specular factor is 1 for any exponent.
        Ray ray = FakeShadingContext.rayFrom(v(-3, 0, 4), Vec3.ZERO);
        FakeShadingContext shading = new FakeShadingContext().light(v(3, 0, 4), v(25, 25, 25));
        Vec3 L = phong(v(1, 0, 0), v(0, 0, 1), 100).shade(hit, ray, shading, 0);
        // I/r² = 1; diffuse n·l = 0.8
        assertVec(v(0.8, 0, 1), L, TOL);
    }

    @Test
    public void specularIsNotGatedByNDotL() {
        // Light below the surface's plane: l = (4, 0, −3)/5, n·l = −0.6 < 0, so no diffuse.
        // Eye straight above: e = (0, 0, 1); l + e = (0.8, 0, 0.4), n·h = 0.4/√0.8 = 1/√5 > 0,
        // (n·h)² = 0.2. r² = 25 and I = 25, so I/r² = 1: specular = ks · 0.2.
        Ray ray = FakeShadingContext.rayFrom(v(0, 0, 7), Vec3.ZERO);
        FakeShadingContext shading = new FakeShadingContext().light(v(4, 0, -3), v(25, 25, 25));
        Vec3 L = phong(v(1, 1, 1), v(1, 0.5, 0.25), 2).shade(hit, ray, shading, 0);
        assertVec(v(0.2, 0.1, 0.05), L, TOL);
        assertEquals("a nonzero specular term needs its shadow test", 1, shading.shadowRays);
    }

    @Test
    public void lightAndEyeBothFarBelowGiveZeroAndNoShadowRay() {
        // A grazing eye above the surface and a light well below it, so that l + e points below: n·h < 0.
        Ray ray = FakeShadingContext.rayFrom(v(5, 0, 1), Vec3.ZERO);     // e = (5, 0, 1)/√26
        FakeShadingContext shading = new FakeShadingContext().light(v(-1, 0, -5), v(9, 9, 9)); // l = (−1, 0, −5)/√26
        // l + e = (4, 0, −4)/√26: n·h < 0, n·l < 0, so both terms vanish.
        assertVec(Vec3.ZERO, phong(Vec3.ONE, Vec3.ONE, 1).shade(hit, ray, shading, 0), 0);
        assertEquals(0, shading.shadowRays);
    }

    @Test
    public void shadowedLightAddsNothing() {
        Ray ray = FakeShadingContext.rayFrom(v(3, 0, 4), Vec3.ZERO);
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 2), v(4, 4, 4));
        shading.lit = position -> false;
        assertVec(Vec3.ZERO, phong(Vec3.ONE, Vec3.ONE, 2).shade(hit, ray, shading, 0), 0);
        assertEquals(1, shading.shadowRays);
    }

    @Test(expected = IllegalArgumentException.class)
    public void negativeExponentIsRejected() {
        new Phong().setExponent(-1);
    }
}
