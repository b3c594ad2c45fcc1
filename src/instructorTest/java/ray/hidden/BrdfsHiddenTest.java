package ray.hidden;

import static org.junit.Assert.assertTrue;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.shading.Brdf;
import ray.shading.LambertianBrdf;
import ray.shading.PhongBrdf;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden BRDF cases: seeded random reflectances, normals and pairs of directions above the surface,
 * the Lambertian's ρd/π and the Phong's ρd/π + ks · max(0, n·h)^p with whole exponents from 1 to 300,
 * each against the formula worked out here another way (n·h = (n·l + n·v)/√(2 + 2 l·v) for unit l
 * and v, no half vector made); and the hard cases, as extra credit: directions in the tangent plane
 * (finite, the formula's value) and exponents of a hundred thousand (1 where h = n, 0 elsewhere, never NaN).
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class BrdfsHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final int CASES = 400;

    /** A random unit vector in the hemisphere around {@code n} (n·x ≥ 0.01: above the surface). */
    private static Vec3 above(Random random, Vec3 n) {
        while (true) {
            Vec3 x = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            if (x.lengthSquared() < 1e-6) {
                continue;
            }
            x = x.normalized();
            if (x.dot(n) < 0) {
                x = x.negate();
            }
            if (x.dot(n) >= 0.01) {
                return x;
            }
        }
    }

    private static Vec3 color(Random random) {
        return new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
    }

    /** The Phong BRDF's highlight factor max(0, n·h)^p, with n·h found without a half vector. */
    private static double highlight(Vec3 n, Vec3 l, Vec3 v, double p) {
        double nh = (n.dot(l) + n.dot(v)) / Math.sqrt(2 + 2 * l.dot(v));
        return Math.pow(Math.max(0, nh), p);
    }

    private static void check(Brdf brdf, Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v, Vec3 expected, String what) {
        Vec3 result = brdf.value(rhoD, n, l, v);
        String message = what + ": " + brdf.getClass().getSimpleName() + ".value(ρd " + rhoD + ", n " + n + ", l " + l + ", v " + v
                + ") returned " + result + "; expected " + expected;
        assertTrue(message, result != null);
        for (int axis = 0; axis < 3; axis++) {
            double e = expected.get(axis);
            double r = result.get(axis);
            assertTrue(message, Double.isFinite(r) && Math.abs(r - e) <= 1e-9 * Math.max(1, Math.abs(e)));
        }
    }

    @Test
    @Points(value = 3, visibility = Visibility.HIDDEN)
    public void lambertianOnRandomDirections() {
        Random random = new Random(20190901);
        for (int k = 0; k < CASES; k++) {
            Vec3 n = above(random, new Vec3(random.nextGaussian(), random.nextGaussian(), 1).normalized());
            Vec3 rhoD = color(random);
            check(new LambertianBrdf(), rhoD, n, above(random, n), above(random, n), rhoD.times(1 / Math.PI), "case " + k + " (ρd/π)");
        }
    }

    @Test
    @Points(value = 4, visibility = Visibility.HIDDEN)
    public void phongOnRandomDirections() {
        Random random = new Random(20191015);
        for (int k = 0; k < CASES; k++) {
            Vec3 n = above(random, new Vec3(random.nextGaussian(), 1, random.nextGaussian()).normalized());
            Vec3 l = above(random, n);
            Vec3 v = above(random, n);
            Vec3 rhoD = color(random);
            Vec3 ks = color(random);
            int p = 1 + random.nextInt(300);
            Vec3 expected = rhoD.times(1 / Math.PI).plus(ks.times(highlight(n, l, v, p)));
            check(new PhongBrdf(ks, p), rhoD, n, l, v, expected, "case " + k + " (ρd/π + ks·max(0, n·h)^" + p + ")");
        }
    }

    /** Light or eye exactly in the tangent plane (n·l = 0 or n·v = 0, the two not opposite): the formula's finite value. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void directionsInTheTangentPlane() {
        Vec3 n = new Vec3(0, 0, 1);
        Vec3 rhoD = new Vec3(0.4, 0.5, 0.6);
        Vec3 ks = new Vec3(0.7, 0.8, 0.9);
        Vec3[][] pairs = {{new Vec3(1, 0, 0), n}, {n, new Vec3(0, 1, 0)}, {new Vec3(1, 0, 0), new Vec3(0, 1, 0)},
            {new Vec3(0.6, 0, 0.8), new Vec3(-0.8, 0.6, 0)}};
        for (Vec3[] pair : pairs) {
            check(new LambertianBrdf(), rhoD, n, pair[0], pair[1], rhoD.times(1 / Math.PI), "a grazing direction");
            Vec3 expected = rhoD.times(1 / Math.PI).plus(ks.times(highlight(n, pair[0], pair[1], 9)));
            check(new PhongBrdf(ks, 9), rhoD, n, pair[0], pair[1], expected, "a grazing direction");
        }
    }

    /** p = 100000: exactly ks where h = n (mirror directions), and no highlight at n·h = 0.999, never NaN. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void aHugeExponent() {
        Vec3 n = new Vec3(0, 0, 1);
        Vec3 ks = new Vec3(1, 0.5, 0.25);
        check(new PhongBrdf(ks, 100000), Vec3.ZERO, n, new Vec3(0.6, 0, 0.8), new Vec3(-0.6, 0, 0.8), ks, "h = n: 1^100000 = 1");
        check(new PhongBrdf(ks, 100000), Vec3.ZERO, n, new Vec3(0.6, 0, 0.8), n, Vec3.ZERO, "(3/√10)^100000 underflows to 0");
    }
}
