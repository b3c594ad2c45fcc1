package ray.hidden;

import static org.junit.Assert.assertTrue;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.shading.DirectLighting;
import ray.shading.Lambertian;
import ray.shading.Light;
import ray.shading.Phong;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden light-loop cases: seeded random points, normals, eyes and one to six lights (some blocked),
 * Lambertian and Phong with whole exponents from 1 to 300, each checked against the formula worked
 * out here channel by channel; and the hard cases, as extra credit: a light exactly at the point
 * (it adds nothing, never NaN), a light exactly in the tangent plane, an eye grazing the surface,
 * and a point a million units from the origin lit from a unit away.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class LightingHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final int CASES = 300;

    /** One case: a point, its normal, the eye, the lights and which are blocked; no mirror rays. */
    private static final class Case extends HiddenLitPoint<Case> {
        Case(Vec3 location, Vec3 normal, Vec3 eye) {
            super(location, normal, eye);
        }

        @Override
        protected Case self() {
            return this;
        }

        /** The formula, channel by channel: Σ (kd · max(0, n·l) + ks · max(0, n·h)^p) · I / r² over the unblocked lights. */
        double[] expected(Vec3 kd, Vec3 ks, int p) {
            double[] sum = new double[3];
            Vec3 n = hit.normal;
            double eLength = ray.direction.length();
            double[] e = {-ray.direction.x / eLength, -ray.direction.y / eLength, -ray.direction.z / eLength};
            for (int k = 0; k < lights.size(); k++) {
                Light light = lights.get(k);
                double[] d = {light.getPosition().x - hit.location.x, light.getPosition().y - hit.location.y,
                        light.getPosition().z - hit.location.z};
                double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                if (blocked.get(k) || r2 == 0) {
                    continue;
                }
                double r = Math.sqrt(r2);
                double nl = (n.x * d[0] + n.y * d[1] + n.z * d[2]) / r;
                double[] h = {d[0] / r + e[0], d[1] / r + e[1], d[2] / r + e[2]};
                double hLength = Math.sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
                double nh = (n.x * h[0] + n.y * h[1] + n.z * h[2]) / hLength;
                double specular = ks == null ? 0 : Math.pow(Math.max(0, nh), p);
                for (int c = 0; c < 3; c++) {
                    double reflected = kd.get(c) * Math.max(0, nl) + (ks == null ? 0 : ks.get(c) * specular);
                    sum[c] += reflected * light.getIntensity().get(c) / r2;
                }
            }
            return sum;
        }
    }

    private static void check(Case c, DirectLighting shader, double[] expected, String what) {
        Vec3 result = shader.shade(c.hit, c.ray, c.context(), 0);
        String message = what + " at " + c.describe() + " returned " + result + "; expected (" + expected[0] + ", " + expected[1] + ", "
                + expected[2] + ")";
        assertTrue(message, result != null && result.isFinite());
        for (int axis = 0; axis < 3; axis++) {
            assertTrue(message, Math.abs(result.get(axis) - expected[axis]) <= 1e-9 * Math.max(1, Math.abs(expected[axis])));
        }
    }

    private static Vec3 unit(Random random) {
        while (true) {
            Vec3 v = new Vec3(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1);
            double l2 = v.lengthSquared();
            if (l2 > 0.01 && l2 <= 1) {
                return v.normalized();
            }
        }
    }

    private static Vec3 color(Random random) {
        return new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
    }

    /** A random case: the eye on the normal's side, the lights anywhere within 5 units (in front or behind). */
    private static Case randomCase(Random random) {
        Vec3 location = new Vec3(10 * random.nextDouble() - 5, 10 * random.nextDouble() - 5, 10 * random.nextDouble() - 5);
        Vec3 normal = unit(random);
        Vec3 toEye = unit(random);
        if (toEye.dot(normal) < 0.05) {
            toEye = toEye.minus(normal.times(2 * toEye.dot(normal) - 0.1)).normalized();
        }
        Case c = new Case(location, normal, location.plus(toEye.times(0.5 + 8 * random.nextDouble())));
        int lights = 1 + random.nextInt(6);
        for (int k = 0; k < lights; k++) {
            Vec3 position = location.plus(unit(random).times(0.2 + 5 * random.nextDouble()));
            c.light(position, color(random).times(1 + 50 * random.nextDouble()), random.nextInt(4) == 0);
        }
        return c;
    }

    @Test
    @Points(value = 4, visibility = Visibility.HIDDEN)
    public void lambertianOnRandomScenes() {
        Random random = new Random(0x4C414D42L);
        for (int k = 0; k < CASES; k++) {
            Case c = randomCase(random);
            Vec3 kd = color(random);
            check(c, new Lambertian(kd), c.expected(kd, null, 0), "Lambertian.shade (kd = " + kd + ")");
        }
    }

    @Test
    @Points(value = 4, visibility = Visibility.HIDDEN)
    public void phongOnRandomScenes() {
        Random random = new Random(0x50484F4EL);
        int[] exponents = {1, 2, 3, 7, 20, 64, 100, 300};
        for (int k = 0; k < CASES; k++) {
            Case c = randomCase(random);
            Vec3 kd = color(random);
            Vec3 ks = color(random);
            int p = exponents[random.nextInt(exponents.length)];
            check(c, phong(kd, ks, p), c.expected(kd, ks, p), "Phong.shade (kd = " + kd + ", ks = " + ks + ", p = " + p + ")");
        }
    }

    private static Phong phong(Vec3 kd, Vec3 ks, int p) {
        Phong phong = new Phong();
        phong.setDiffuseColor(kd);
        phong.setSpecularColor(ks);
        phong.setExponent(p);
        return phong;
    }

    /** Many lights at once: the sum of twenty, half of them blocked. */
    @Test
    @Points(value = 2, visibility = Visibility.HIDDEN)
    public void twentyLights() {
        Random random = new Random(20);
        Case c = new Case(Vec3.ZERO, new Vec3(0, 1, 0), new Vec3(1, 3, 2));
        for (int k = 0; k < 20; k++) {
            c.light(new Vec3(4 * random.nextDouble() - 2, 0.5 + 3 * random.nextDouble(), 4 * random.nextDouble() - 2), color(random),
                    k % 2 == 1);
        }
        Vec3 kd = new Vec3(0.3, 0.6, 0.9);
        Vec3 ks = new Vec3(0.5, 0.4, 0.3);
        check(c, new Lambertian(kd), c.expected(kd, null, 0), "Lambertian.shade");
        check(c, phong(kd, ks, 30), c.expected(kd, ks, 30), "Phong.shade (p = 30)");
    }

    /** A light exactly at the point has no direction: it adds nothing, and nothing is NaN. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void aLightAtThePointAddsNothing() {
        Case c = new Case(new Vec3(1, 2, 3), new Vec3(0, 0, 1), new Vec3(1, 2, 8)).light(new Vec3(1, 2, 3), new Vec3(5, 5, 5), false)
                .light(new Vec3(1, 2, 5), new Vec3(4, 4, 4), false);
        Vec3 kd = new Vec3(0.5, 0.5, 0.5);
        check(c, new Lambertian(kd), new double[] {0.5, 0.5, 0.5}, "Lambertian.shade (a light at the point itself adds nothing)");
        check(c, phong(kd, Vec3.ONE, 10), new double[] {1.5, 1.5, 1.5}, "Phong.shade (a light at the point itself adds nothing)");
    }

    /** A light exactly in the tangent plane (n·l = 0): no diffuse term; Phong's highlight still counts. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void aLightInTheTangentPlane() {
        Case c = new Case(Vec3.ZERO, new Vec3(0, 0, 1), new Vec3(0, 0, 5)).light(new Vec3(3, 0, 0), new Vec3(9, 9, 9), false);
        Vec3 kd = new Vec3(1, 1, 1);
        check(c, new Lambertian(kd), new double[] {0, 0, 0}, "Lambertian.shade");
        // h = normalize((1, 0, 0) + (0, 0, 1)): n·h = √½, squared ½; I/r² = 1.
        check(c, phong(kd, Vec3.ONE, 2), new double[] {0.5, 0.5, 0.5}, "Phong.shade");
    }

    /** An eye grazing the surface, a hair above its plane: finite, and as the formula says. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void aGrazingEye() {
        Case c = new Case(Vec3.ZERO, new Vec3(0, 0, 1), new Vec3(1e4, 0, 1e-8)).light(new Vec3(-1, 0, 1), new Vec3(2, 2, 2), false);
        Vec3 kd = new Vec3(0.25, 0.5, 0.75);
        Vec3 ks = new Vec3(1, 1, 1);
        check(c, phong(kd, ks, 5), c.expected(kd, ks, 5), "Phong.shade");
    }

    /** A point a million units from the origin, lit from a unit away: what matters is the vector between them. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void farFromTheOrigin() {
        Vec3 far = new Vec3(1e6, -2e6, 3e6);
        Case c = new Case(far, new Vec3(0, 0, 1), far.plus(new Vec3(0, 0, 4))).light(far.plus(new Vec3(0, 0, 1)), new Vec3(1, 2, 3), false);
        Vec3 kd = new Vec3(0.5, 0.5, 0.5);
        check(c, new Lambertian(kd), new double[] {0.5, 1, 1.5}, "Lambertian.shade");
        check(c, phong(kd, new Vec3(0.5, 0.5, 0.5), 40), new double[] {1, 2, 3}, "Phong.shade");
    }
}
