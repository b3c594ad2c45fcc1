package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;

import java.util.Random;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Sphere;

/**
 * Tangent rays: impact parameter exactly r (axis-aligned rays with dyadic radii, where the doubles can
 * express it: the oracle confirms Δ' = 0 exactly), one ulp either side of it, and random rays within
 * 4 ulps of tangency. Each is a clean hit (finite t &gt; 0, finite location at distance r from the
 * center, unit normal) or a clean miss (false, record untouched), never NaN.
 */
public class SphereTangentRayTest {
    private static final Vec3 CENTER = new Vec3(7, -3, 12);
    private static final double[] RADII = {1, 0.75, 3, 1024, 1.0 / 1024, 524288};
    /** Powers of two, so d/|d| is exact and the tangent ray's l = f − (f·d̂)d̂ has exact length r. */
    private static final double[] LENGTHS = {1, 0.5, 4};

    @Test
    public void exactlyTangentAxisRayTouchesAtOnePointWithTheOffsetAxisAsNormal() {
        for (double r : RADII) {
            for (double length : LENGTHS) {
                forEachAxisPair((along, offset) -> {
                    // Start 5r back along `along`, r off to the side along `offset`: the line touches the
                    // sphere at CENTER + r·offset, at t = 5r/length. Every coordinate is exact.
                    Ray ray = new Ray(CENTER.plus(along.times(-5 * r)).plus(offset.times(r)), along.times(length));
                    String what = "r " + r + ", " + ray;
                    assertEquals(what + ": exactly tangent", 0, ExactSphere.of(ray, CENTER, r).quarterDiscriminant.signum());
                    IntersectionRecord out = new IntersectionRecord();
                    assertTrue(what, new Sphere(CENTER, r).intersect(out, ray));
                    assertEquals(what, 5 * r / length, out.t, 0);
                    assertVec(what, CENTER.plus(offset.times(r)), out.location, 0);
                    assertVec(what, offset, out.normal, 0);
                });
            }
        }
    }

    /**
     * The origin moved one ulp (of its own coordinate) toward or away from the center. The sphere sees
     * f = o − c; when that difference rounds the nudge away (an origin coordinate near 0 with r = 3:
     * 0 + 4.9e-324 − (−3) = 3), the ray it sees is exactly tangent, and a tangent ray hits. Where the
     * nudge survives in f (256 of the 288 cases: 6 radii, 24 axis pairs, 2 sides), the result matches
     * the exact classification.
     */
    @Test
    public void oneUlpInsideTheTangentHitsAndOneUlpOutsideMisses() {
        int[] survived = {0};
        for (double r : RADII) {
            forEachAxisPair((along, offset) -> {
                for (int side = -1; side <= 1; side += 2) {
                    Vec3 tangentOrigin = CENTER.plus(along.times(-5 * r)).plus(offset.times(r));
                    Vec3 origin = nudge(tangentOrigin, offset, side);
                    Ray ray = new Ray(origin, along);
                    ExactSphere exact = ExactSphere.of(ray, CENTER, r);
                    assertEquals("oracle: side " + side + ", " + ray, side < 0, exact.hit);
                    IntersectionRecord out = new IntersectionRecord();
                    boolean hit = new Sphere(CENTER, r).intersect(out, ray);
                    assertClean(out, hit, CENTER, r, "r " + r + ", " + ray);
                    if (!origin.minus(CENTER).equals(tangentOrigin.minus(CENTER))) {
                        assertEquals("r " + r + ", " + ray, exact.hit, hit);
                        survived[0]++;
                    } else {
                        assertTrue("seen as exactly tangent: r " + r + ", " + ray, hit);
                    }
                }
            });
        }
        assertEquals("cases whose nudge survives o − c", 256, survived[0]);
    }

    /**
     * Random centers (within 1e3 of the origin), radii 10^U(−3, 3), directions and direction lengths;
     * impact parameter r·(1 + kε), k an integer in [−4, 4]. No claim about hit or miss (the rounded
     * inputs decide that); only that each result is clean.
     */
    @Test
    public void nearTangentRandomRaysAreCleanHitsOrCleanMisses() {
        Random random = new Random(701);
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            double r = Math.pow(10, -3 + 6 * random.nextDouble());
            Vec3 center = unit(random).times(1e3 * random.nextDouble());
            Vec3 w = unit(random);
            Vec3 side = unit(random);
            Vec3 perpendicular = side.minus(w.times(side.dot(w))).normalized();
            double impact = r * (1 + (random.nextInt(9) - 4) * Math.ulp(1.0));
            Vec3 origin = center.plus(perpendicular.times(impact)).minus(w.times(r * (2 + 8 * random.nextDouble())));
            Ray ray = new Ray(origin, w.times(Math.pow(10, -2 + 4 * random.nextDouble())));
            IntersectionRecord out = new IntersectionRecord();
            boolean hit = new Sphere(center, r).intersect(out, ray);
            assertClean(out, hit, center, r, "r " + r + ", " + ray);
            hits += hit ? 1 : 0;
        }
        // Both outcomes occur (measured 10,236 hits of 20,000), so both kinds of cleanliness were checked.
        assertTrue("hits " + hits, hits > 5_000 && hits < 15_000);
    }

    private static void assertClean(IntersectionRecord out, boolean hit, Vec3 center, double r, String what) {
        if (!hit) {
            assertEquals(what + ": t untouched", Double.POSITIVE_INFINITY, out.t, 0);
            assertNull(what + ": location untouched", out.location);
            assertNull(what + ": normal untouched", out.normal);
            return;
        }
        assertTrue(what + ": t " + out.t, Double.isFinite(out.t) && out.t > 0);
        assertTrue(what + ": location " + out.location, out.location.isFinite());
        assertTrue(what + ": normal " + out.normal, out.normal.isFinite());
        assertEquals(what + ": |normal|", 1, out.normal.length(), 4 * Math.ulp(1.0));
        // Re-projected: on the sphere to the rounding of center + r·n (ulps of |center| + r).
        assertEquals(what + ": |location − center|", r, out.location.minus(center).length(), 4 * Math.ulp(center.maxAbs() + r));
        assertTrue(what + ": surface " + out.surface, out.surface instanceof Sphere);
    }

    private static Vec3 nudge(Vec3 p, Vec3 axis, int side) {
        // axis is ±x, ±y or ±z: step that coordinate one ulp in the direction side·axis.
        double x = axis.x == 0 ? p.x : step(p.x, side * axis.x);
        double y = axis.y == 0 ? p.y : step(p.y, side * axis.y);
        double z = axis.z == 0 ? p.z : step(p.z, side * axis.z);
        return new Vec3(x, y, z);
    }

    private static double step(double value, double sign) {
        return sign > 0 ? Math.nextUp(value) : Math.nextDown(value);
    }

    private interface AxisPair {
        void accept(Vec3 along, Vec3 offset);
    }

    /** Every ordered pair of distinct signed axes: 6 ray directions × 4 sideways offsets. */
    private static void forEachAxisPair(AxisPair body) {
        Vec3[] axes = {new Vec3(1, 0, 0), new Vec3(-1, 0, 0), new Vec3(0, 1, 0), new Vec3(0, -1, 0), new Vec3(0, 0, 1), new Vec3(0, 0, -1)};
        for (Vec3 along : axes) {
            for (Vec3 offset : axes) {
                if (along.dot(offset) == 0) {
                    body.accept(along, offset);
                }
            }
        }
    }

    private static Vec3 unit(Random random) {
        return new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalized();
    }
}
