package ray.hidden;

import static org.junit.Assert.assertTrue;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.shading.BeckmannDistribution;
import ray.shading.Fresnel;
import ray.shading.GgxDistribution;
import ray.shading.MicrofacetBrdf;
import ray.shading.MicrofacetDistribution;
import ray.shading.MicrofacetOracle;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden microfacet cases: seeded random normals and directions anywhere above the surface (down to
 * n·x = 1e-3), roughnesses from 0.01 to 3 and refractive indices from 0.3 to 5 (below 1: total
 * internal reflection at grazing angles), each of D, G1, F and the whole BRDF against the 40-digit
 * oracle; and the hard cases together: a half vector in the tangent plane, light and eye grazing at
 * n·x = 1e-150, α = 1e-4, nt = 1. Every value must be finite.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class MicrofacetHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final int CASES = 300;

    private static Vec3 unit(Random random) {
        while (true) {
            Vec3 x = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            if (x.lengthSquared() > 1e-6) {
                return x.normalized();
            }
        }
    }

    private static Vec3 above(Random random, Vec3 n) {
        while (true) {
            Vec3 x = unit(random);
            if (x.dot(n) < 0) {
                x = x.negate();
            }
            if (x.dot(n) >= 1e-3) {
                return x;
            }
        }
    }

    private static void check(double result, double expected, double relative, String what) {
        String message = what + " returned " + result + "; expected " + expected;
        assertTrue(message, Double.isFinite(result) && Math.abs(result - expected) <= relative * Math.max(Math.abs(expected), 1e-200));
    }

    private static MicrofacetDistribution distribution(String name, double alpha) {
        return name.equals(MicrofacetDistribution.BECKMANN) ? new BeckmannDistribution(alpha) : new GgxDistribution(alpha);
    }

    @Test
    @Points(3)
    public void distributionsAgainstTheOracle() {
        Random random = new Random(44);
        for (int k = 0; k < CASES; k++) {
            Vec3 n = unit(random);
            Vec3 h = random.nextInt(10) == 0 ? unit(random) : above(random, n); // now and then below the surface
            double alpha = 0.01 + 2.99 * random.nextDouble() * random.nextDouble();
            String what = "case " + k + ": normalDistribution(n " + n + ", h " + h + ") with α = " + alpha;
            check(new BeckmannDistribution(alpha).normalDistribution(n, h), MicrofacetOracle.beckmannD(alpha, n, h), 1e-9, "Beckmann " + what);
            check(new GgxDistribution(alpha).normalDistribution(n, h), MicrofacetOracle.ggxD(alpha, n, h), 1e-9, "GGX " + what);
        }
    }

    @Test
    @Points(3)
    public void maskingAgainstTheOracle() {
        Random random = new Random(45);
        for (int k = 0; k < CASES; k++) {
            Vec3 n = unit(random);
            Vec3 x = above(random, n);
            Vec3 h = above(random, n);
            double alpha = 0.01 + 2.99 * random.nextDouble() * random.nextDouble();
            String what = "case " + k + ": masking(x " + x + ", n " + n + ", h " + h + ") with α = " + alpha;
            double a = Math.abs(x.dot(n)) / (alpha * x.cross(n).length());
            if (Math.abs(a - 1.6) < 1e-9) {
                continue; // the rational fit's cut-off: either side is the course's
            }
            check(new BeckmannDistribution(alpha).masking(x, n, h), MicrofacetOracle.beckmannG1(alpha, x, n, h), 1e-9, "Beckmann " + what);
            check(new GgxDistribution(alpha).masking(x, n, h), MicrofacetOracle.ggxG1(alpha, x, n, h), 1e-9, "GGX " + what);
        }
    }

    @Test
    @Points(3)
    public void fresnelAgainstTheOracle() {
        Random random = new Random(46);
        for (int k = 0; k < CASES; k++) {
            double nt = 0.3 + 4.7 * random.nextDouble();
            double c = random.nextDouble();
            check(new Fresnel(nt).reflectance(c), MicrofacetOracle.fresnel(nt, c), 1e-9, "case " + k + ": Fresnel (nt = " + nt + ").reflectance(" + c + ")");
        }
    }

    @Test
    @Points(3)
    public void theBrdfAgainstTheOracle() {
        Random random = new Random(47);
        for (int k = 0; k < CASES; k++) {
            Vec3 n = unit(random);
            Vec3 l = above(random, n);
            Vec3 v = above(random, n);
            String name = k % 2 == 0 ? MicrofacetDistribution.BECKMANN : MicrofacetDistribution.GGX;
            double alpha = 0.01 + 2.99 * random.nextDouble() * random.nextDouble();
            double nt = 1 + 4 * random.nextDouble();
            Vec3 rhoD = new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
            Vec3 kmf = new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
            double facets = MicrofacetOracle.specular(name, alpha, nt, n, l, v);
            Vec3 result = new MicrofacetBrdf(kmf, name, alpha, nt).value(rhoD, n, l, v);
            String what = "case " + k + ": MicrofacetBrdf (" + name + ", α = " + alpha + ", nt = " + nt + ").value(ρd " + rhoD + ", n " + n
                    + ", l " + l + ", v " + v + ")";
            assertTrue(what + " returned null", result != null);
            for (int axis = 0; axis < 3; axis++) {
                check(result.get(axis), rhoD.get(axis) / Math.PI + kmf.get(axis) * facets, 1e-9, what + ", channel " + axis);
            }
        }
    }

    /** Extra credit within the task (as the visible hard cases are): where the textbook forms divide by zero. */
    @Test
    @Points(value = 3, bonus = true, visibility = Visibility.HIDDEN)
    public void theHardCasesTogether() {
        Vec3 n = new Vec3(0, 1, 0);
        for (String name : new String[] {MicrofacetDistribution.BECKMANN, MicrofacetDistribution.GGX}) {
            check(distribution(name, 0.4).normalDistribution(n, new Vec3(0, 0, 1)), 0, 0, name + " D with h in the tangent plane");
            Vec3 l = new Vec3(1, 1e-150, 0).normalized();
            Vec3 v = new Vec3(0, 1e-150, 1).normalized();
            double facets = MicrofacetOracle.specular(name, 0.4, 1.5, n, l, v);
            check(new MicrofacetBrdf(Vec3.ONE, name, 0.4, 1.5).value(Vec3.ZERO, n, l, v).x, facets, 1e-9, name + " f with light and eye at n·x = 1e-150");
            Vec3 l2 = new Vec3(0.3, 1, 0.1).normalized();
            Vec3 v2 = new Vec3(-0.3, 1, -0.1).normalized();
            check(new MicrofacetBrdf(Vec3.ONE, name, 1e-4, 1.5).value(Vec3.ZERO, n, l2, v2).x, MicrofacetOracle.specular(name, 1e-4, 1.5, n, l2, v2),
                    1e-9, name + " f at α = 1e-4, light and eye mirrored");
            check(new MicrofacetBrdf(Vec3.ONE, name, 0.4, 1).value(Vec3.ZERO, n, l2, new Vec3(0.5, 1, 0.2).normalized()).x, 0, 0,
                    name + " f with nt = 1 (no interface)");
        }
    }
}
