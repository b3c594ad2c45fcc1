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
 * Checks MicrofacetBrdf.value, f = ρd/π + k_mf·F·D·G1(l)·G1(v)/(4|n·l||n·v|): the course's check
 * values, hand-worked cases (a steep light and eye, nt = 1, a tiny roughness; the grazing angles where the
 * textbook form divides by zero are {@link MicrofacetHardCasesBonusTest}'s) and
 * seeded random cases against {@link MicrofacetOracle}. It uses this task's own D, G1 and F, so a
 * mistake in one of them shows here too; MicrofacetTermsTest says which.
 */
@Points(1)
public class MicrofacetBrdfTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 UP = v(0, 0, 1);
    private static final Vec3 L = v(Math.sin(Math.toRadians(60)), 0, Math.cos(Math.toRadians(60)));
    private static final Vec3 V = v(Math.sin(Math.toRadians(-30)), 0, Math.cos(Math.toRadians(-30)));

    private static void check(MicrofacetBrdf brdf, Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v, Vec3 expected, double relative, String why) {
        Vec3 result = brdf.value(rhoD, n, l, v);
        String message = "MicrofacetBrdf (" + brdf.distribution().name() + ", α = " + brdf.distribution().getAlpha() + ", nt = "
                + brdf.fresnel().getNt() + ", k_mf = " + brdf.getMicrofacetColor() + ").value(ρd " + rhoD + ", n " + n + ", l " + l
                + ", v " + v + ") returned " + result + "; expected " + expected + Hints.fix(why.isEmpty() ? "" : " (" + why + ")");
        assertTrue(message, result != null);
        for (int axis = 0; axis < 3; axis++) {
            double e = expected.get(axis);
            assertTrue(message, Double.isFinite(result.get(axis)) && Math.abs(result.get(axis) - e) <= relative * Math.max(Math.abs(e), 1e-200));
        }
    }

    private static Vec3 gray(double x) {
        return v(x, x, x);
    }

    /**
     * The course's check: ρd = 1, k_mf = 1, α = 0.5, nt = 1.5, l 60° and v −30° from n. Worked out to
     * 40 digits, Beckmann gives 0.3498099628051773 and GGX 0.3399154924812475; the course printed
     * 0.3498099620956212 and 0.3399154913418668, about 1e-9 lower, because its code rounded π and two
     * square roots to float. Both are checked: to 1e-12 of the exact value and 5e-9 of the course's.
     */
    @Test
    @Points(3)
    public void theCoursesCheckValues() {
        check(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.BECKMANN, 0.5, 1.5), Vec3.ONE, UP, L, V, gray(0.3498099628051773), 1e-12,
                "1/π + F D G1(l) G1(v) / (4 cos 60° cos 30°), F = 0.0502399, D = 1.0975170, G1 = 0.9894916 and 1");
        check(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.GGX, 0.5, 1.5), Vec3.ONE, UP, L, V, gray(0.3399154924812475), 1e-12,
                "1/π + F D G1(l) G1(v) / (4 cos 60° cos 30°), F = 0.0502399, D = 0.8827783, G1 = 0.8610017 and 0.9799920");
        check(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.BECKMANN, 0.5, 1.5), Vec3.ONE, UP, L, V, gray(0.3498099620956212), 5e-9,
                "the course's printed value");
        check(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.GGX, 0.5, 1.5), Vec3.ONE, UP, L, V, gray(0.3399154913418668), 5e-9,
                "the course's printed value");
    }

    /**
     * The view mirrored below the surface gives f = 0, all of it (the course's check gives 0), and so
     * does the light below; the light and view swapped above the surface give the check value again
     * (f is symmetric in l and v).
     */
    @Test
    @Points(2)
    public void belowTheSurfaceFIsZero() {
        Vec3 below = v(V.x, 0, -V.z);
        MicrofacetBrdf beckmann = new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.BECKMANN, 0.5, 1.5);
        check(beckmann, Vec3.ONE, UP, V, L, gray(0.3498099628051773), 1e-12, "l and v swapped: the same f");
        check(beckmann, Vec3.ONE, UP, L, below, Vec3.ZERO, 0, "n·v < 0");
        check(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.GGX, 0.5, 1.5), Vec3.ONE, UP, below, V, Vec3.ZERO, 0, "n·l < 0");
    }

    /**
     * Light and eye along n: h = n, F = R0 = 0.04 (nt 1.5), D = 1/(πα²), both G1 = 1, so the facets add
     * k_mf · 0.04 / (4 π α²) per channel; with α = 0.2, k_mf = (1, 0.5, 0.25) and ρd = (0.3, 0.6, 0.9).
     */
    @Test
    @Points(2)
    public void headOn() {
        Vec3 rhoD = v(0.3, 0.6, 0.9);
        Vec3 kmf = v(1, 0.5, 0.25);
        double facets = 0.04 / (4 * Math.PI * 0.04);
        Vec3 expected = rhoD.times(1 / Math.PI).plus(kmf.times(facets));
        check(new MicrofacetBrdf(kmf, MicrofacetDistribution.BECKMANN, 0.2, 1.5), rhoD, UP, UP, UP, expected, 1e-12, "ρd/π + k_mf R0/(4πα²)");
        check(new MicrofacetBrdf(kmf, MicrofacetDistribution.GGX, 0.2, 1.5), rhoD, UP, UP, UP, expected, 1e-12, "ρd/π + k_mf R0/(4πα²)");
    }

    /** nt = 1: no interface, F = 0, so f is ρd/π alone, at any angle. */
    @Test
    public void noInterfaceLeavesTheDiffusePart() {
        Vec3 rhoD = v(0.2, 0.4, 0.8);
        check(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.GGX, 0.3, 1), rhoD, UP, L, V, rhoD.times(1 / Math.PI), 1e-12, "F = 0");
    }

    /** A steep light and eye, n·l = n·v = 0.001: the facets' part is finite and the formula's (the rational G1 at a = 0.001/(α sinθ)). */
    @Test
    public void steepLightAndEye() {
        Vec3 l = v(0.6, 0.8, 0.001).normalized();
        Vec3 view = v(-0.8, 0.6, 0.001).normalized();
        for (String distribution : new String[] {MicrofacetDistribution.BECKMANN, MicrofacetDistribution.GGX}) {
            double facets = MicrofacetOracle.specular(distribution, 0.3, 1.5, UP, l, view);
            check(new MicrofacetBrdf(Vec3.ONE, distribution, 0.3, 1.5), Vec3.ZERO, UP, l, view, gray(facets), 1e-9,
                    "F D G1(l) G1(v) / (4 n·l n·v) with n·l = n·v = 0.001");
        }
    }

    /** A near-mirror, α = 1e-4, light and eye mirrored about n: D = 1e8/π, so f is large but exact. */
    @Test
    public void aNearMirror() {
        Vec3 l = v(0.6, 0, 0.8);
        Vec3 view = v(-0.6, 0, 0.8);
        double facets = MicrofacetOracle.specular(MicrofacetDistribution.GGX, 1e-4, 1.5, UP, l, view);
        check(new MicrofacetBrdf(Vec3.ONE, MicrofacetDistribution.GGX, 1e-4, 1.5), Vec3.ZERO, UP, l, view, gray(facets), 1e-10,
                "h = n: F(0.8) · 1/(π 1e-8) · G1 G1 / (4 · 0.64)");
    }

    /** 200 seeded random cases (both distributions, α from 0.05 to 1, nt from 1 to 3, colored ρd and k_mf) against the 40-digit oracle to 1e-9. */
    @Test
    @Points(3)
    public void randomCasesAgainstAHighPrecisionOracle() {
        Random random = new Random(2019);
        for (int k = 0; k < 200; k++) {
            Vec3 n = MicrofacetTermsTest.unit(random);
            Vec3 l = MicrofacetTermsTest.above(random, n);
            Vec3 view = MicrofacetTermsTest.above(random, n);
            String distribution = k % 2 == 0 ? MicrofacetDistribution.BECKMANN : MicrofacetDistribution.GGX;
            double alpha = 0.05 + 0.95 * random.nextDouble();
            double nt = 1 + 2 * random.nextDouble();
            Vec3 rhoD = v(random.nextDouble(), random.nextDouble(), random.nextDouble());
            Vec3 kmf = v(random.nextDouble(), random.nextDouble(), random.nextDouble());
            double facets = MicrofacetOracle.specular(distribution, alpha, nt, n, l, view);
            check(new MicrofacetBrdf(kmf, distribution, alpha, nt), rhoD, n, l, view, rhoD.times(1 / Math.PI).plus(kmf.times(facets)), 1e-9,
                    "case " + k);
        }
    }
}
