package ray.shading;

import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks the microfacet BRDF's three factors, each alone: D and G1 of the Beckmann and GGX
 * distributions and the exact Fresnel factor F. The values are the course's check point (worked out
 * to 40 digits), hand-computed cases, the hard cases (h in the tangent plane, a grazing direction, a tiny
 * and a large α, nt = 1 and nt &lt; 1), and seeded random directions against {@link MicrofacetOracle}.
 * The angles where the textbook forms divide by zero are {@link MicrofacetHardCasesBonusTest}'s.
 */
@Points(1)
public class MicrofacetTermsTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 UP = v(0, 0, 1);
    /** The course's check point: normal +z, l 60° and v −30° from it in the xz plane, so h is 15° from n and l·h = cos 45°. */
    private static final Vec3 L = v(Math.sin(Math.toRadians(60)), 0, Math.cos(Math.toRadians(60)));
    private static final Vec3 V = v(Math.sin(Math.toRadians(-30)), 0, Math.cos(Math.toRadians(-30)));
    private static final Vec3 H = L.plus(V).normalized();

    private static void check(double result, double expected, double relative, String call, String why) {
        String message = call + " returned " + result + "; expected " + expected + Hints.fix(why.isEmpty() ? "" : " (" + why + ")");
        assertTrue(message, Double.isFinite(result));
        // Below 1e-200 a value is zero for any picture; the subnormal range has no relative precision to ask for.
        assertTrue(message, Math.abs(result - expected) <= relative * Math.max(Math.abs(expected), 1e-200));
    }

    private static void d(MicrofacetDistribution distribution, Vec3 n, Vec3 h, double expected, double relative, String why) {
        check(distribution.normalDistribution(n, h), expected, relative,
                distribution.name() + " (α = " + distribution.getAlpha() + ").normalDistribution(n " + n + ", h " + h + ")", why);
    }

    private static void g1(MicrofacetDistribution distribution, Vec3 x, Vec3 n, Vec3 h, double expected, double relative, String why) {
        check(distribution.masking(x, n, h), expected, relative,
                distribution.name() + " (α = " + distribution.getAlpha() + ").masking(x " + x + ", n " + n + ", h " + h + ")", why);
    }

    private static void f(double nt, double cosine, double expected, double relative, String why) {
        check(new Fresnel(nt).reflectance(cosine), expected, relative, "Fresnel (nt = " + nt + ").reflectance(" + cosine + ")", why);
    }

    /** h along n: tanθ = 0, so both distributions give 1/(πα²); for α = 0.5 that is 4/π. */
    @Test
    @Points(2)
    public void dAlongTheNormalIsOneOverPiAlphaSquared() {
        d(new BeckmannDistribution(0.5), UP, UP, 4 / Math.PI, 1e-12, "exp(0)/(π α² · 1) = 4/π");
        d(new GgxDistribution(0.5), UP, UP, 4 / Math.PI, 1e-12, "α²/(π · 1 · α⁴) = 4/π");
    }

    /** The course's check point, h 15° from n: Beckmann D = 1.0975169661591833, GGX D = 0.8827783286398071 (40-digit values). */
    @Test
    @Points(2)
    public void dAtTheCoursesCheckPoint() {
        d(new BeckmannDistribution(0.5), UP, H, 1.0975169661591833, 1e-12, "exp(−tan²15°/0.25) / (π · 0.25 · cos⁴15°)");
        d(new GgxDistribution(0.5), UP, H, 0.8827783286398071, 1e-12, "0.25 / (π cos⁴15° (0.25 + tan²15°)²)");
    }

    /** h below the surface: no facets point there, D = 0 (never negative, never NaN); mirrored above it, D is the formula's. */
    @Test
    public void dIsZeroOnlyBelowTheSurface() {
        Vec3 above = v(0.6, 0, 0.8);
        Vec3 below = v(0.6, 0, -0.8);
        d(new BeckmannDistribution(0.3), UP, above, MicrofacetOracle.beckmannD(0.3, UP, above), 1e-12, "tan²θ = 0.5625");
        d(new BeckmannDistribution(0.3), UP, below, 0, 0, "n·h < 0");
        d(new GgxDistribution(0.3), UP, above, MicrofacetOracle.ggxD(0.3, UP, above), 1e-12, "tan²θ = 0.5625");
        d(new GgxDistribution(0.3), UP, below, 0, 0, "n·h < 0");
    }

    /** h in the tangent plane (n·h = 0) is not above the surface: D = 0 for both, never NaN (Beckmann's tan²θ is infinite there). */
    @Test
    public void dWithHInTheTangentPlane() {
        Vec3 tangent = v(1, 0, 0);
        d(new BeckmannDistribution(0.5), UP, tangent, 0, 0, "n·h = 0 is not above the surface");
        d(new GgxDistribution(0.5), UP, tangent, 0, 0, "n·h = 0 is not above the surface");
        Vec3 steep = v(1, 0, 0.01).normalized();
        d(new BeckmannDistribution(0.5), UP, steep, MicrofacetOracle.beckmannD(0.5, UP, steep), 1e-10, "exp(−4e4) underflows to 0");
        d(new GgxDistribution(0.5), UP, steep, MicrofacetOracle.ggxD(0.5, UP, steep), 1e-10, "α²/(π cos⁴θ (α² + tan²θ)²) with tanθ = 100");
    }

    /** A near-mirror, α = 1e-4: along n, D = 1/(π · 1e-8); 1° away the Beckmann exponential underflows (D = 0) and GGX's tail is tiny but exact. */
    @Test
    public void aTinyRoughness() {
        double alpha = 1e-4;
        d(new BeckmannDistribution(alpha), UP, UP, 1 / (Math.PI * alpha * alpha), 1e-12, "1/(πα²)");
        d(new GgxDistribution(alpha), UP, UP, 1 / (Math.PI * alpha * alpha), 1e-12, "1/(πα²)");
        Vec3 oneDegree = v(Math.sin(Math.toRadians(1)), 0, Math.cos(Math.toRadians(1)));
        d(new BeckmannDistribution(alpha), UP, oneDegree, 0, 0, "exp(−tan²1°/1e-8) underflows: 0");
        d(new GgxDistribution(alpha), UP, oneDegree, MicrofacetOracle.ggxD(alpha, UP, oneDegree), 1e-10, "α²/(π cos⁴θ (α² + tan²θ)²)");
    }

    /** The course's check point: Beckmann G1(l) = 0.9894916495056011 (a = 1/(0.5 tan 60°) < 1.6) and G1(v) = 1 (a ≥ 1.6); GGX 0.8610017480861208 and 0.9799919935935928. */
    @Test
    @Points(2)
    public void maskingAtTheCoursesCheckPoint() {
        g1(new BeckmannDistribution(0.5), L, UP, H, 0.9894916495056011, 1e-12, "the rational fit at a = 2/√3");
        g1(new BeckmannDistribution(0.5), V, UP, H, 1, 0, "a = 2/tan 30° ≥ 1.6: 1");
        g1(new GgxDistribution(0.5), L, UP, H, 0.8610017480861208, 1e-12, "2 / (1 + √(1 + 0.25 tan²60°))");
        g1(new GgxDistribution(0.5), V, UP, H, 0.9799919935935928, 1e-12, "2 / (1 + √(1 + 0.25 tan²30°))");
    }

    /** Along the normal nothing is hidden: G1 = 1 (Beckmann's a is infinite there, not NaN). */
    @Test
    public void maskingAlongTheNormalIsOne() {
        Vec3 h = v(0.2, 0, 1).normalized();
        g1(new BeckmannDistribution(0.5), UP, UP, h, 1, 0, "tanθ = 0, a = ∞ ≥ 1.6");
        g1(new GgxDistribution(0.5), UP, UP, h, 1, 1e-15, "2 / (1 + √1)");
    }

    /** x on the other side of the facet than of the surface (x·h < 0 < x·n): hidden, G1 = 0; the same x with h on its side is seen. */
    @Test
    public void maskingBehindTheFacetIsZero() {
        Vec3 away = v(1, 0, 0.2).normalized();
        Vec3 toward = v(-1, 0, 0.2).normalized();
        Vec3 x = v(-0.8, 0, 0.6);
        g1(new BeckmannDistribution(0.5), x, UP, away, 0, 0, "x·h < 0 while x·n > 0");
        g1(new BeckmannDistribution(0.5), x, UP, toward, MicrofacetOracle.beckmannG1(0.5, x, UP, toward), 1e-12, "x·h > 0: a = 0.6/(0.5 · 0.8) = 1.5");
        g1(new GgxDistribution(0.5), x, UP, away, 0, 0, "x·h < 0 while x·n > 0");
        g1(new GgxDistribution(0.5), x, UP, toward, MicrofacetOracle.ggxG1(0.5, x, UP, toward), 1e-12, "x·h > 0");
    }

    /** A grazing direction, n·x = 1e-9: G1 falls to nearly 0, finite (a = n·x/(α sinθ), or tanθ ≈ 1e9). */
    @Test
    @Points(2)
    public void maskingAtAGrazingDirection() {
        Vec3 x = v(1, 0, 1e-9).normalized();
        Vec3 h = v(0.3, 0, 1).normalized();
        g1(new BeckmannDistribution(0.5), x, UP, h, MicrofacetOracle.beckmannG1(0.5, x, UP, h), 1e-9, "a = 2e-9: 3.535a/(1 + …)");
        g1(new GgxDistribution(0.5), x, UP, h, MicrofacetOracle.ggxG1(0.5, x, UP, h), 1e-9, "2/(1 + √(1 + α² · 1e18))");
    }

    /** Head on (c = 1), F is R0 = ((nt − 1)/(nt + 1))²: 0.04 for glass; at grazing (c = 0) F = 1. */
    @Test
    @Points(2)
    public void fresnelHeadOnAndAtGrazing() {
        f(1.5, 1, 0.04, 1e-12, "g = nt, so ½ R0 (1 + 1) = R0 = (0.5/2.5)²");
        f(2, 1, 1.0 / 9, 1e-12, "R0 = (1/3)²");
        f(1.5, 0, 1, 1e-12, "c = 0: ½ · 1 · (1 + 1)");
    }

    /** The course's check point: |l·h| = cos 45°, nt = 1.5: F = 0.05023991101223594 (not Schlick's 0.0421). */
    @Test
    @Points(2)
    public void fresnelAtTheCoursesCheckPoint() {
        f(1.5, Math.abs(L.dot(H)), 0.05023991101223594, 1e-12, "g = √(nt² − 1 + c²) = √1.75");
    }

    /** nt = 1 is no interface: F = 0 at every angle. nt < 1 past the critical angle: total reflection, F = 1; before it, the formula. */
    @Test
    public void fresnelWithoutAndBelowAnInterface() {
        f(1, 0.3, 0, 0, "g = c, so (g − c) = 0");
        f(1, 1, 0, 0, "g = c");
        f(0.5, 0.5, 1, 0, "g² = 0.25 − 1 + 0.25 < 0: total internal reflection");
        f(0.5, 0.95, MicrofacetOracle.fresnel(0.5, 0.95), 1e-12, "g² = 0.25 − 1 + 0.9025 > 0");
    }

    /** α ≥ 1 (very rough): the formulas hold as they are; checked against the 40-digit oracle at α = 1 and 2. */
    @Test
    public void largeRoughness() {
        Vec3 h = v(0.5, 0.2, 1).normalized();
        Vec3 x = v(-0.9, 0.1, 0.4).normalized();
        for (double alpha : new double[] {1, 2}) {
            d(new BeckmannDistribution(alpha), UP, h, MicrofacetOracle.beckmannD(alpha, UP, h), 1e-12, "");
            d(new GgxDistribution(alpha), UP, h, MicrofacetOracle.ggxD(alpha, UP, h), 1e-12, "");
            g1(new BeckmannDistribution(alpha), x, UP, h, MicrofacetOracle.beckmannG1(alpha, x, UP, h), 1e-12, "");
            g1(new GgxDistribution(alpha), x, UP, h, MicrofacetOracle.ggxG1(alpha, x, UP, h), 1e-12, "");
        }
    }

    /** 200 seeded random normals, directions and roughnesses from 0.05 to 1, each term against the 40-digit oracle to 1e-10. */
    @Test
    @Points(3)
    public void randomCasesAgainstAHighPrecisionOracle() {
        Random random = new Random(4620);
        for (int k = 0; k < 200; k++) {
            Vec3 n = unit(random);
            Vec3 l = above(random, n);
            Vec3 view = above(random, n);
            Vec3 h = l.plus(view).normalized();
            double alpha = 0.05 + 0.95 * random.nextDouble();
            double nt = 1 + 2 * random.nextDouble();
            String why = "case " + k;
            d(new BeckmannDistribution(alpha), n, h, MicrofacetOracle.beckmannD(alpha, n, h), 1e-10, why);
            d(new GgxDistribution(alpha), n, h, MicrofacetOracle.ggxD(alpha, n, h), 1e-10, why);
            g1(new BeckmannDistribution(alpha), l, n, h, MicrofacetOracle.beckmannG1(alpha, l, n, h), 1e-10, why);
            g1(new GgxDistribution(alpha), view, n, h, MicrofacetOracle.ggxG1(alpha, view, n, h), 1e-10, why);
            double c = Math.abs(l.dot(h));
            f(nt, c, MicrofacetOracle.fresnel(nt, c), 1e-10, why);
        }
    }

    static Vec3 unit(Random random) {
        while (true) {
            Vec3 x = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            if (x.lengthSquared() > 1e-6) {
                return x.normalized();
            }
        }
    }

    /** A random unit vector at least 0.05 above the plane of n (n·x ≥ 0.05). */
    static Vec3 above(Random random, Vec3 n) {
        while (true) {
            Vec3 x = unit(random);
            if (x.dot(n) < 0) {
                x = x.negate();
            }
            if (x.dot(n) >= 0.05) {
                return x;
            }
        }
    }
}
