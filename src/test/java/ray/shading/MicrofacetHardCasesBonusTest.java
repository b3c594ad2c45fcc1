package ray.shading;

import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Bonus (extra credit) tests of the microfacet factors and BRDF where the textbook formulas divide by
 * zero: a half vector a hair above the tangent plane (cos²θ underflows to 0, so tan²θ is infinite
 * and Beckmann's exp(−∞)/(π α² · 0) is 0/0), and a light and an eye grazing the surface at
 * n·l = n·v = 1e-170 (their product underflows to 0, so F·D·G1·G1/(4 n·l n·v) is 0/0). The values
 * are finite there, and the 40-digit oracle says what they are; the regular tests keep away from
 * these angles, so the textbook forms earn every regular point.
 */
@Points(value = 1, bonus = true)
public class MicrofacetHardCasesBonusTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 UP = v(0, 0, 1);

    private static void check(double result, double expected, String call, String why) {
        String message = call + " returned " + result + "; expected " + expected + Hints.fix(" (" + why + ")");
        assertTrue(message, Double.isFinite(result) && Math.abs(result - expected) <= 1e-9 * Math.max(Math.abs(expected), 1e-200));
    }

    /**
     * h a hair above the tangent plane, n·h = 1e-200: Beckmann's D is 0 (the exponential of −1e400
     * vanishes; 0, not 0/0) and GGX's is α²/(π (α² cos²θ + sin²θ)²) → α²/π = 0.25/π.
     */
    @Test
    @Points(value = 2, bonus = true)
    public void dWithHAHairAboveTheTangentPlane() {
        Vec3 almost = v(1, 0, 1e-200).normalized();
        check(new BeckmannDistribution(0.5).normalDistribution(UP, almost), 0, "Beckmann (α = 0.5).normalDistribution(n " + UP + ", h "
                + almost + ")", "exp(−tan²θ/α²) underflows to 0 before cos⁴θ does: 0, never 0/0");
        check(new GgxDistribution(0.5).normalDistribution(UP, almost), MicrofacetOracle.ggxD(0.5, UP, almost), "GGX (α = 0.5)"
                + ".normalDistribution(n " + UP + ", h " + almost + ")", "cos⁴θ (α² + tan²θ)² = (α² cos²θ + sin²θ)² → 1");
    }

    /**
     * Grazing light and eye, n·l = n·v = 1e-170: the product of the cosines (1e-340) underflows to 0,
     * yet f is finite: each G1 over its own cosine stays about 3.535/(α sinθ) (Beckmann) or 2/α (GGX).
     */
    @Test
    @Points(value = 2, bonus = true)
    public void grazingLightAndEyeStayFinite() {
        Vec3 l = v(0.6, 0.8, 1e-170).normalized();
        Vec3 view = v(-0.8, 0.6, 1e-170).normalized();
        for (String distribution : new String[] {MicrofacetDistribution.BECKMANN, MicrofacetDistribution.GGX}) {
            double facets = MicrofacetOracle.specular(distribution, 0.3, 1.5, UP, l, view);
            Vec3 f = new MicrofacetBrdf(Vec3.ONE, distribution, 0.3, 1.5).value(Vec3.ZERO, UP, l, view);
            check(f == null ? Double.NaN : f.x, facets, "MicrofacetBrdf (" + distribution + ", α = 0.3, nt = 1.5).value(ρd 0, n " + UP
                    + ", l " + l + ", v " + view + ").x", "F D (G1(l)/n·l)(G1(v)/n·v)/4, each masking term over its own cosine");
        }
    }
}
