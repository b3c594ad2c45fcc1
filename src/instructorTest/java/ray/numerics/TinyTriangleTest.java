package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.Random;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Triangle;

/**
 * Tiny triangles (sizes 1e-3, 1e-4, 1e-5, 1e-6) seen from 0.5–2 sizes away ({@link TinyTriangleRays}):
 * every ray aimed inside hits, at the target. The solution has no absolute epsilon, so binary scaling
 * of a whole configuration changes nothing but t (scaled exactly), while the textbook early-out
 * |det| &lt; 1e-8 throws tiny triangles away.
 *
 * <p>Measured (10,000 rays per size and direction, seeds as below): the solution hits all 80,000,
 * with t and the hit point as close to the target's as the inputs' rounding allows (TOLERANCE).
 * Möller–Trumbore with |det| &lt; 1e-8 misses, with unit directions, none at size 1e-3 (0.02% over
 * 1e6 rays in TriangleSweep), 75% at 1e-4 and 100% at 1e-5 and 1e-6; with the direction
 * origin → target (|d| ≈ size), 100% at every size. The test requires at least 50%, 99% and 99%
 * of the unit-direction rays at 1e-4, 1e-5 and 1e-6, and 99% of the others. Without the epsilon,
 * Möller–Trumbore and Cramer's rule hit all of them: the epsilon, not the formula, loses them.
 * Under binary scaling by 2^−10 … 2^−20 of 10,000 unit-size hits (unit directions), the solution's
 * β and γ stay the same bit for bit and t scales exactly; the epsilon test loses 69% of them (the
 * test requires more than half).
 */
public class TinyTriangleTest {
    private static final double[] SIZES = {1e-3, 1e-4, 1e-5, 1e-6};
    private static final int RAYS = 10_000;
    /**
     * The points are rounded to an ulp of their coordinates (about 1e-16 below 1), whatever the size,
     * so t's relative error and the hit's distance from the target grow as 1/size: measured at most
     * 1.0e-15/size and 0.9e-15. The tolerance is ten times that.
     */
    private static final double TOLERANCE = 1e-14;

    @Test
    public void everyRayAimedInsideATinyTriangleHitsAtTheTarget() {
        for (double size : SIZES) {
            for (boolean unit : new boolean[] {true, false}) {
                TinyTriangleRays rays = new TinyTriangleRays(Double.doubleToLongBits(size), size, unit);
                for (int i = 0; i < RAYS; i++) {
                    Ray ray = rays.next();
                    IntersectionRecord out = new IntersectionRecord();
                    boolean hit = rays.triangle.intersect(out, ray);
                    double tError = Math.abs(out.t - rays.targetT()) / rays.targetT();
                    if (!hit || !(tError <= TOLERANCE / size) || !(out.location.minus(rays.target).length() <= TOLERANCE)) {
                        String what = "size " + size + ", ray " + i + " " + ray + " aimed inside " + rays.triangle + " at " + rays.target;
                        assertTrue(what + " must hit", hit);
                        assertEquals(what + ": t", rays.targetT(), out.t, TOLERANCE / size * rays.targetT());
                        assertEquals(what + ": distance of the hit from the target", 0, out.location.minus(rays.target).length(), TOLERANCE);
                    }
                }
            }
        }
    }

    @Test
    public void textbookEpsilonMissesTinyTriangles() {
        double[] unitMinimum = {0, 0.5, 0.99, 0.99};
        for (int s = 0; s < SIZES.length; s++) {
            double unitRate = epsilonMissRate(SIZES[s], true);
            double aimRate = epsilonMissRate(SIZES[s], false);
            assertTrue("|det| < 1e-8 missed " + unitRate + " of size " + SIZES[s] + " with unit directions", unitRate >= unitMinimum[s]);
            assertTrue("|det| < 1e-8 missed " + aimRate + " of size " + SIZES[s] + " with d = target − origin", aimRate >= 0.99);
        }
    }

    @Test
    public void binaryScalingChangesNothingButT() {
        Random random = new Random(21);
        TinyTriangleRays rays = new TinyTriangleRays(22, 1, true);
        int epsilonLost = 0;
        for (int i = 0; i < RAYS; i++) {
            Ray ray = rays.next();
            IntersectionRecord unscaled = new IntersectionRecord();
            assertTrue("unit-size ray " + i + " must hit", rays.triangle.intersect(unscaled, ray));
            // Multiplying every point by a power of two is exact, and so is every step of the solution.
            double scale = Math.scalb(1.0, -10 - random.nextInt(11));
            Triangle small = new Triangle(rays.triangle.getV0().times(scale), rays.triangle.getV1().times(scale),
                    rays.triangle.getV2().times(scale));
            Ray scaled = new Ray(ray.origin.times(scale), ray.direction);
            IntersectionRecord out = new IntersectionRecord();
            String what = "ray " + i + " scaled by " + scale;
            assertTrue(what + " must still hit", small.intersect(out, scaled));
            assertEquals(what + ": t", unscaled.t * scale, out.t, 0);
            assertEquals(what + ": beta", unscaled.beta, out.beta, 0);
            assertEquals(what + ": gamma", unscaled.gamma, out.gamma, 0);
            epsilonLost += TextbookTriangles.MOLLER_TRUMBORE_EPSILON.intersect(small, new IntersectionRecord(), scaled) ? 0 : 1;
        }
        assertTrue("the textbook epsilon lost " + epsilonLost + " of " + RAYS + " scaled-down hits (measured 6,919)",
                epsilonLost > RAYS / 2);
    }

    private static double epsilonMissRate(double size, boolean unit) {
        TinyTriangleRays rays = new TinyTriangleRays(Double.doubleToLongBits(size), size, unit);
        int misses = 0;
        for (int i = 0; i < RAYS; i++) {
            Ray ray = rays.next();
            misses += TextbookTriangles.MOLLER_TRUMBORE_EPSILON.intersect(rays.triangle, new IntersectionRecord(), ray) ? 0 : 1;
        }
        return misses / (double) RAYS;
    }
}
