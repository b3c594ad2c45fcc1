package ray.numerics;

import static org.junit.Assert.assertTrue;

import org.junit.Test;
import ray.IntersectionRecord;

/**
 * Rays starting 0.5–1.5 units above a sphere of radius 1e3…1e6 and heading into it (HugeSphereRays,
 * 500 seeded rays per radius and placement): the solution hits, with t &gt; 0 and the near root.
 *
 * <p>How close to the exact root depends on what the doubles allow. Above a ground sphere centered
 * on an axis, with origins on a 1/64 grid, c = f·f − r² is exact and the stable quadratic's c/q keeps
 * the near root to a few ulps (measured max 3.4 ulps; the textbook (−b − √Δ)/2a cancels and is off by
 * up to 2.9e6 ulps at R = 1e6). With the sphere anywhere, o − c and f·f round at the scale R, so the
 * exact root of the given doubles is ill-conditioned: moving the inputs by one relative ulp moves
 * t ≈ 1 by about R·ε. No double algorithm without extra precision can then promise t to a few ulps;
 * the solution stays within the condition bound κ (ExactSphere.conditionBound; measured max 0.32 κ,
 * up to 1.9e6 ulps of t at R = 1e6: a displacement of the hit point along the ray comparable to one
 * ulp of its coordinates). The textbook formula stays within 0.51 κ here too: on this case the stable
 * quadratic only pays off when c is exact. Measured figures: SphereSweep, 1e5 rays per row.
 */
public class HugeSphereNearRootTest {
    private static final int RAYS_PER_RADIUS = 500;

    /** Bound: 4 ulps of t; measured max 3.4 (SphereSweep, 1e5 rays per radius). */
    @Test
    public void aboveGroundSphereNearRootIsWithinFourUlps() {
        double textbookWorst = 0;
        for (int e = 3; e <= 6; e++) {
            HugeSphereRays rays = HugeSphereRays.ground(400 + e, Math.pow(10, e));
            for (int i = 0; i < RAYS_PER_RADIUS; i++) {
                SphereCase k = rays.next();
                ExactSphere exact = k.exact();
                IntersectionRecord out = hitOrFail(k, exact);
                assertTrue("ulps off " + exact.ulpsOff(out.t) + ", t " + out.t + " vs " + exact.t + ": " + k, exact.ulpsOff(out.t) <= 4);
                IntersectionRecord textbook = new IntersectionRecord();
                if (k.textbook().intersect(textbook, k.ray)) {
                    textbookWorst = Math.max(textbookWorst, exact.ulpsOff(textbook.t));
                }
            }
        }
        // The case is a real test: the textbook near root loses about log2(R) bits here.
        assertTrue("textbook worst " + textbookWorst + " ulps", textbookWorst > 1e5);
    }

    /** Bound: |t − t*| ≤ 2κ, as for every condition-bound test; measured max 0.32 κ (SphereSweep). */
    @Test
    public void sphereAnywhereNearRootIsWithinTheConditionBound() {
        for (int e = 3; e <= 6; e++) {
            HugeSphereRays rays = HugeSphereRays.anywhere(500 + e, Math.pow(10, e));
            for (int i = 0; i < RAYS_PER_RADIUS; i++) {
                SphereCase k = rays.next();
                ExactSphere exact = k.exact();
                IntersectionRecord out = hitOrFail(k, exact);
                double kappa = exact.conditionBound(k.ray, k.center);
                assertTrue("t " + out.t + " vs " + exact.t + " (κ " + kappa + "): " + k, exact.absoluteError(out.t) <= 2 * kappa);
            }
        }
    }

    /** A hit with t &gt; 0 that is the near root: the exact roots are about 1 and 2R apart. */
    private static IntersectionRecord hitOrFail(SphereCase k, ExactSphere exact) {
        assertTrue("exact oracle must hit: " + k, exact.hit);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue("robust sphere missed: " + k, k.robust().intersect(out, k.ray));
        assertTrue("t " + out.t + " not positive: " + k, out.t > 0);
        // The near root is at most about 1.5·√2/|d| (height ≤ 1.5, tilt ≤ 45°); the far one near 2R/|d|.
        assertTrue("t " + out.t + " is not the near root " + exact.t + ": " + k, Math.abs(out.t - exact.t.doubleValue()) < 1e-3 * exact.t.doubleValue());
        return out;
    }
}
