package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Checks Sphere.intersect on hand-computed cases: which root is returned, the exact t, location
 * and unit outward normal, the strict (start, end) segment, and that a miss leaves the record alone.
 * Each miss is paired with a nearby hit so that a sphere that never hits fails too.
 */
public class SphereTest {
    private static final double TOL = 1e-14;
    private final Sphere unit = new Sphere(Vec3.ZERO, 1);

    @Test
    public void hitFromOutsideReturnsNearRoot() {
        // |(0,0,5) − t(0,0,1)|² = 1 → t = 4 or 6.
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1))));
        assertEquals(4, out.t, TOL);
        assertVec(v(0, 0, 1), out.location, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
        assertSame(unit, out.surface);
    }

    @Test
    public void hitFromInsideReturnsFarRootWithOutwardNormal() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(unit.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1))));
        assertEquals(1, out.t, TOL);
        assertVec(v(0, 0, -1), out.location, TOL);
        // Outward, not flipped toward the ray's origin.
        assertVec(v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void offCenterSphereGivesHandComputedHit() {
        // Center (1.6, 2.8, 10), radius 2; ray (1,2,3) + t(0,0,1) passes at distance |(−0.6,−0.8)| = 1
        // from the center, so it enters at z = 10 − √(4 − 1): t = 7 − √3, normal (−0.6, −0.8, −√3)/2.
        Sphere sphere = new Sphere(v(1.6, 2.8, 10), 2);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(sphere.intersect(out, new Ray(v(1, 2, 3), v(0, 0, 1))));
        double root3 = Math.sqrt(3);
        assertEquals(7 - root3, out.t, TOL);
        assertVec(v(1, 2, 10 - root3), out.location, TOL);
        assertVec(v(-0.3, -0.4, -root3 / 2), out.normal, TOL);
        assertSame(sphere, out.surface);
    }

    @Test
    public void nonUnitDirectionScalesT() {
        // Direction twice as long: the same point at half the t.
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -2))));
        assertEquals(2, out.t, TOL);
        assertVec(v(0, 0, 1), out.location, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void normalIsUnitLengthForALargeSphere() {
        Sphere big = new Sphere(v(0, 0, -100), 50);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(big.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1))));
        assertEquals(50, out.t, TOL * 100);
        assertVec(v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void sphereBehindTheRayIsMissedButHitWhenFacingIt() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, 1))));
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1))));
    }

    @Test
    public void rayPassingBesideTheSphereMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse(unit.intersect(out, new Ray(v(0, 1.5, 5), v(0, 0, -1))));
        assertTrue(unit.intersect(out, new Ray(v(0, 0.5, 5), v(0, 0, -1))));
        // z = √(1 − 0.25) on entry.
        assertEquals(5 - Math.sqrt(0.75), out.t, TOL);
    }

    @Test
    public void tangentRayHitsAtTheTangentPointOrMissesCleanly() {
        // (−5,1,0) + t(1,0,0) touches the unit sphere only at (0,1,0), t = 5.
        IntersectionRecord out = new IntersectionRecord();
        if (unit.intersect(out, new Ray(v(-5, 1, 0), v(1, 0, 0)))) {
            assertEquals(5, out.t, TOL);
            assertVec(v(0, 1, 0), out.location, TOL);
            assertVec(v(0, 1, 0), out.normal, TOL);
        } else {
            assertEquals(Double.POSITIVE_INFINITY, out.t, 0);
        }
        // Just inside the tangent the ray hits, with finite values on the sphere.
        IntersectionRecord near = new IntersectionRecord();
        assertTrue(unit.intersect(near, new Ray(v(-5, 1 - 1e-6, 0), v(1, 0, 0))));
        assertTrue(near.location.isFinite() && near.normal.isFinite());
        // The entry is at x = −√(1 − y²), y = 1 − 1e-6: −√(2e-6 − 1e-12).
        assertEquals(5 - Math.sqrt(2e-6 - 1e-12), near.t, 1e-12);
        assertEquals(1, near.location.length(), 1e-15);
    }

    @Test
    public void segmentEndingBeforeTheSphereMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 0, 3.9)));
        // The end is exclusive: t = 4 exactly is not inside (0, 4).
        assertFalse(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 0, 4)));
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 0, 4.1)));
        assertEquals(4, out.t, TOL);
    }

    @Test
    public void startBeyondNearRootReturnsFarRoot() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 4.5, Double.POSITIVE_INFINITY)));
        assertEquals(6, out.t, TOL);
        assertVec(v(0, 0, -1), out.location, TOL);
        assertVec(v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void startIsExclusive() {
        IntersectionRecord out = new IntersectionRecord();
        // Start exactly at the near root: the far root is the hit.
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 4, Double.POSITIVE_INFINITY)));
        assertEquals(6, out.t, TOL);
        // Start exactly at the far root: nothing is left.
        IntersectionRecord miss = new IntersectionRecord();
        assertFalse(unit.intersect(miss, new Ray(v(0, 0, 5), v(0, 0, -1), 6, Double.POSITIVE_INFINITY)));
    }

    @Test
    public void segmentBetweenTheRootsMisses() {
        // Both roots (4 and 6) lie outside (4.5, 5.5).
        IntersectionRecord out = new IntersectionRecord();
        assertFalse(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 4.5, 5.5)));
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 4.5, 6.5)));
    }

    @Test
    public void missLeavesTheRecordUntouched() {
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        IntersectionRecord before = copyOf(out);
        assertFalse(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, 1))));
        assertFalse(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1), 0, 3)));
        assertFalse(unit.intersect(out, new Ray(v(0, 2, 5), v(0, 0, -1))));
        assertUntouched(before, out);
        // The same record is filled by a hit.
        assertTrue(unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1))));
        assertEquals(4, out.t, TOL);
        assertSame(unit, out.surface);
    }

    @Test
    public void rayIsNotChangedByIntersect() {
        Ray ray = new Ray(v(0, 0, 5), v(0, 0, -1), 0.5, 10);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(unit.intersect(out, ray));
        assertEquals(0.5, ray.start, 0);
        assertEquals(10, ray.end, 0);
        assertVec(v(0, 0, 5), ray.origin, 0);
        assertVec(v(0, 0, -1), ray.direction, 0);
    }

    @Test
    public void invalidRadiusIsRejected() {
        for (double bad : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            try {
                new Sphere(Vec3.ZERO, bad);
                fail("radius " + bad + " should be rejected");
            } catch (IllegalArgumentException expected) {
                // the message names the radius
            }
        }
    }
}
