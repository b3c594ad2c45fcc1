package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.testing.RandomVectors.randomInBall;
import static ray.testing.RandomVectors.randomVec;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Property test of Sphere.intersect on seeded random rays aimed at random spheres: every ray hits,
 * the hit lies on the sphere, the normal is the unit (p − c)/r, and t matches the smallest positive
 * root of the quadratic computed in 34-digit decimal arithmetic.
 *
 * <p>The tolerances admit the textbook formula: for a small sphere far from the ray's origin,
 * b² − 4ac cancels and costs the location and the normal's length up to ~2e-9 (relative) on these
 * rays, while a stable formulation stays near 1e-13. Any real mistake (a wrong root, a normal not
 * divided by the radius) is off by far more than 1e-7.
 */
@Points(2)
public class SphereRandomTest {
    private static final MathContext MC = MathContext.DECIMAL128;
    /** Relative distance from the sphere allowed for the location, and the normal's allowed length error. */
    private static final double ON_SPHERE = 1e-7;

    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    @Test
    public void hitsAgreeWithHighPrecisionRootsOfTheQuadratic() {
        Random random = new Random(20240601);
        for (int i = 0; i < 1000; i++) {
            Vec3 center = randomVec(random, 20);
            double radius = Math.pow(10, -2 + 3 * random.nextDouble());
            // Some origins are inside the sphere (they hit the far root), most are outside.
            Vec3 origin = random.nextInt(10) == 0
                    ? center.plus(randomInBall(random, 0.9 * radius))
                    : randomVec(random, 20);
            // Aim at a point well inside the sphere, so the ray surely hits and is far from tangent.
            Vec3 target = center.plus(randomInBall(random, 0.9 * radius));
            Vec3 direction = target.minus(origin).times(0.1 + 10 * random.nextDouble());
            Ray ray = new Ray(origin, direction);
            Sphere sphere = new Sphere(center, radius);

            IntersectionRecord out = new IntersectionRecord();
            String what = "random ray " + i + ", " + ray + ", aimed inside " + sphere;
            double expected = referenceT(origin, direction, center, radius);
            assertHitAt(what + " (t is the smallest root in (0, ∞))", sphere, out, ray, expected, 1e-10 * Math.abs(expected));
            assertSame(what + ": out.surface must be the sphere", sphere, out.surface);
            assertEquals(what + ": the location must lie on the sphere, |location − center| = radius",
                    radius, out.location.minus(center).length(), ON_SPHERE * radius);
            // The location is the ray's point at t (to the precision t allows).
            Vec3 onRay = ray.pointAt(out.t);
            assertEquals(what + ": the location must be ray.pointAt(t)", 0, onRay.minus(out.location).length(),
                    1e-9 * (radius + origin.minus(center).length()));
            Vec3 expectedNormal = out.location.minus(center).times(1 / radius);
            assertEquals(what + ": the normal must be unit length", 1, out.normal.length(), ON_SPHERE);
            assertEquals(what + ": the normal must be " + Hints.wordsOrFormula("the unit outward normal", "(location − center)/radius")
                    + ", it was " + out.normal, 0,
                    out.normal.minus(expectedNormal).length(), ON_SPHERE);
        }
    }

    /** The smallest positive root of a t² + b t + c = 0, from the exact doubles, in 34-digit arithmetic. */
    private static double referenceT(Vec3 p, Vec3 d, Vec3 center, double radius) {
        BigDecimal[] dir = {exact(d.x), exact(d.y), exact(d.z)};
        BigDecimal[] f = {exact(p.x).subtract(exact(center.x)), exact(p.y).subtract(exact(center.y)),
            exact(p.z).subtract(exact(center.z))};
        // a, b and c are exact: sums of products of exact values.
        BigDecimal a = dot(dir, dir);
        BigDecimal b = dot(dir, f).multiply(BigDecimal.valueOf(2));
        BigDecimal c = dot(f, f).subtract(exact(radius).multiply(exact(radius)));
        BigDecimal discriminant = b.multiply(b).subtract(BigDecimal.valueOf(4).multiply(a).multiply(c));
        BigDecimal root = discriminant.sqrt(MC);
        BigDecimal twoA = a.multiply(BigDecimal.valueOf(2));
        BigDecimal near = b.negate().subtract(root).divide(twoA, MC);
        BigDecimal far = b.negate().add(root).divide(twoA, MC);
        return (near.signum() > 0 ? near : far).doubleValue();
    }

    private static BigDecimal exact(double x) {
        return new BigDecimal(x);
    }

    private static BigDecimal dot(BigDecimal[] a, BigDecimal[] b) {
        return a[0].multiply(b[0]).add(a[1].multiply(b[1])).add(a[2].multiply(b[2]));
    }
}
