package ray.hidden;

import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.math.Vec3;
import ray.shading.Brdf;
import ray.shading.LambertianBrdf;
import ray.shading.PhongBrdf;
import ray.shading.ReflectionShader;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden cases of the 2019 reflection shader: seeded random points, normals, eyes, one to six lights
 * (some blocked), the Lambertian or a Phong BRDF and a mirror coefficient (zero in a third of the
 * cases), each against the formula worked out here channel by channel, with the mirror direction
 * and depth checked; and the hard cases, as extra credit: an eye grazing the surface (Schlick's
 * weight near 1), a light exactly at the point, and a mirror a million units from the origin.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class ReflectionHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final int CASES = 300;

    /** One case: a point, its normal, the eye, the lights (some blocked), and the color the mirror direction brings back. */
    private static final class Case extends HiddenLitPoint<Case> {
        final Vec3 sky;
        final List<Vec3> mirrorDirections = new ArrayList<>();
        final List<Integer> mirrorDepths = new ArrayList<>();

        Case(Vec3 location, Vec3 normal, Vec3 eye, Vec3 sky) {
            super(location, normal, eye);
            this.sky = sky;
        }

        @Override
        protected Case self() {
            return this;
        }

        @Override
        protected Vec3 mirror(IntersectionRecord at, Vec3 direction, int depth) {
            mirrorDirections.add(direction);
            mirrorDepths.add(depth);
            return sky;
        }

        /** The formula: Σ f(l, v) ⊙ I · max(0, n·l)/r² over the unblocked lights, plus R ⊙ sky when k_m ≠ 0; 0 when n·v ≤ 0. */
        double[] expected(Brdf brdf, Vec3 rhoD, Vec3 km) {
            double[] sum = new double[3];
            Vec3 n = hit.normal;
            Vec3 v = ray.direction.negate().normalized();
            double nv = n.dot(v);
            if (!(nv > 0)) {
                return sum;
            }
            for (int k = 0; k < lights.size(); k++) {
                Vec3 toLight = lights.get(k).getPosition().minus(hit.location);
                double r2 = toLight.lengthSquared();
                if (blocked.get(k) || r2 == 0) {
                    continue;
                }
                Vec3 l = toLight.normalized();
                double nl = Math.max(0, n.dot(l));
                Vec3 f = brdf.value(rhoD, n, l, v);
                for (int c = 0; c < 3; c++) {
                    sum[c] += f.get(c) * lights.get(k).getIntensity().get(c) * nl / r2;
                }
            }
            if (!km.equals(Vec3.ZERO)) {
                double m = 1 - nv;
                for (int c = 0; c < 3; c++) {
                    sum[c] += (km.get(c) + (1 - km.get(c)) * Math.pow(m, 5)) * sky.get(c);
                }
            }
            return sum;
        }

        @Override
        String describe() {
            return super.describe() + ", the mirror direction bringing back " + sky;
        }
    }

    private static void check(Case c, Brdf brdf, Vec3 rhoD, Vec3 km, String what) {
        ReflectionShader shader = new ReflectionShader("hidden", brdf, rhoD, null, km, null, null);
        Vec3 result = shader.shade(c.hit, c.ray, c.context(), 2);
        double[] expected = c.expected(brdf, rhoD, km);
        String message = what + " with ρd " + rhoD + " and k_m " + km + " at " + c.describe() + " returned " + result + "; expected ("
                + expected[0] + ", " + expected[1] + ", " + expected[2] + ")";
        assertTrue(message, result != null && result.isFinite());
        for (int axis = 0; axis < 3; axis++) {
            assertTrue(message, Math.abs(result.get(axis) - expected[axis]) <= 1e-9 * Math.max(1, Math.abs(expected[axis])));
        }
        boolean mirrors = !km.equals(Vec3.ZERO) && c.hit.normal.dot(c.ray.direction) < 0;
        assertTrue(message + ": " + c.mirrorDirections.size() + " mirror rays asked", c.mirrorDirections.size() == (mirrors ? 1 : 0));
        if (mirrors) {
            Vec3 d = c.ray.direction.normalized();
            Vec3 reflected = d.minus(c.hit.normal.times(2 * d.dot(c.hit.normal)));
            Vec3 asked = c.mirrorDirections.get(0).normalized();
            assertTrue(message + ": the mirror ray went along " + asked + ", not " + reflected, asked.minus(reflected).length() < 1e-9);
            assertTrue(message + ": the mirror ray's depth " + c.mirrorDepths.get(0), c.mirrorDepths.get(0) == 3);
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

    /** A random case: the eye on either side of the surface (a quarter behind), the lights within 5 units. */
    private static Case randomCase(Random random) {
        Vec3 location = new Vec3(10 * random.nextDouble() - 5, 10 * random.nextDouble() - 5, 10 * random.nextDouble() - 5);
        Vec3 normal = unit(random);
        Vec3 toEye = unit(random);
        boolean behind = random.nextInt(4) == 0;
        if ((toEye.dot(normal) < 0.05) != behind) {
            toEye = toEye.minus(normal.times(2 * toEye.dot(normal) + (behind ? 0.1 : -0.1))).normalized();
        }
        Case c = new Case(location, normal, location.plus(toEye.times(0.5 + 8 * random.nextDouble())), color(random).times(3));
        int lights = 1 + random.nextInt(6);
        for (int k = 0; k < lights; k++) {
            c.light(location.plus(unit(random).times(0.2 + 5 * random.nextDouble())), color(random).times(1 + 50 * random.nextDouble()),
                    random.nextInt(4) == 0);
        }
        return c;
    }

    @Test
    @Points(value = 4, visibility = Visibility.HIDDEN)
    public void randomPointsLightsAndMirrors() {
        Random random = new Random(2019_4620);
        for (int k = 0; k < CASES; k++) {
            Case c = randomCase(random);
            Brdf brdf = random.nextBoolean() ? new LambertianBrdf() : new PhongBrdf(color(random), 1 + random.nextInt(200));
            Vec3 km = random.nextInt(3) == 0 ? Vec3.ZERO : color(random);
            check(c, brdf, color(random), km, "case " + k);
        }
    }

    /** An eye a hair above the tangent plane: n·v ≈ 1e-9, so Schlick's weight is nearly 1 in every channel; finite, as the formula. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void aGrazingEye() {
        Case c = new Case(Vec3.ZERO, new Vec3(0, 0, 1), new Vec3(-1, 0, 1e-9), new Vec3(0.5, 1, 2)).light(new Vec3(0, 0, 1),
                new Vec3(5, 5, 5), false);
        check(c, new PhongBrdf(new Vec3(1, 1, 1), 30), new Vec3(0.3, 0.3, 0.3), new Vec3(0.04, 0.5, 1), "a grazing eye");
    }

    /** A light exactly at the shaded point has no direction: it adds nothing, never NaN; the other light still counts. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void aLightAtThePointAddsNothing() {
        Case c = new Case(new Vec3(1, 2, 3), new Vec3(0, 1, 0), new Vec3(1, 5, 3), new Vec3(1, 1, 1)).light(new Vec3(1, 2, 3),
                new Vec3(9, 9, 9), false).light(new Vec3(1, 4, 3), new Vec3(4, 4, 4), false);
        check(c, new LambertianBrdf(), new Vec3(0.5, 0.5, 0.5), Vec3.ZERO, "a light at the point");
    }

    /** A mirror a million units from the origin, lit and seen from a unit away: the same value as at the origin, to 1e-9. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN, bonus = true)
    public void aMirrorFarFromTheOrigin() {
        Vec3 far = new Vec3(1e6, -1e6, 1e6);
        Case c = new Case(far, new Vec3(0, 0, 1), far.plus(new Vec3(0.6, 0, 0.8)), new Vec3(0.2, 0.4, 0.8)).light(far.plus(new Vec3(0, 0.6, 0.8)),
                new Vec3(3, 3, 3), false);
        check(c, new PhongBrdf(new Vec3(0.5, 0.5, 0.5), 20), new Vec3(0.1, 0.2, 0.3), new Vec3(0.3, 0.3, 0.3), "far from the origin");
    }
}
