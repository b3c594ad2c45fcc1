package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTask;
import ray.testing.StudentTaskRule;

/**
 * Checks Sphere.intersect on hand-computed cases: which root is returned, the exact t, location
 * and unit outward normal, the strict (start, end) segment, and that a miss leaves the record alone.
 * Each miss is paired with a nearby hit so that a sphere that never hits fails too.
 */
@Points(value = 1, task = StudentTask.SPHERE)
public class SphereTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.SPHERE);

    private static final double TOL = 1e-14;
    private final Sphere unit = new Sphere(Vec3.ZERO, 1);

    /** From (0,0,5) toward −z with the segment (start, end): it enters the unit sphere at t = 4 and leaves at t = 6. */
    private static Ray fromFiveDown(double start, double end) {
        return new Ray(v(0, 0, 5), v(0, 0, -1), start, end);
    }

    @Test
    @Points(value = 2, task = StudentTask.SPHERE)
    public void hitFromOutsideReturnsNearRoot() {
        // |(0,0,5) − t(0,0,1)|² = 1 → t = 4 or 6.
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (0,0,5) toward −z";
        assertTrue(ray + " must hit the unit sphere (at t = 4)", unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1))));
        assertEquals(ray + " enters the unit sphere at t = 4 (the nearer root)", 4, out.t, TOL);
        assertVec(ray + ": location", v(0, 0, 1), out.location, TOL);
        assertVec(ray + ": normal (location − center)/radius", v(0, 0, 1), out.normal, TOL);
        assertSame(ray + ": out.surface must be the sphere", unit, out.surface);
    }

    @Test
    @Points(value = 2, task = StudentTask.SPHERE)
    public void hitFromInsideReturnsFarRootWithOutwardNormal() {
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from the center (0,0,0) toward −z";
        assertTrue(ray + " must hit the unit sphere from inside (at t = 1)", unit.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1))));
        assertEquals(ray + ": the roots are −1 and 1; only t = 1 is in (0, ∞)", 1, out.t, TOL);
        assertVec(ray + ": location", v(0, 0, -1), out.location, TOL);
        assertVec(ray + ": the normal points outward, (location − center)/radius, even from inside", v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void offCenterSphereGivesHandComputedHit() {
        // Center (1.6, 2.8, 10), radius 2; ray (1,2,3) + t(0,0,1) passes at distance |(−0.6,−0.8)| = 1
        // from the center, so it enters at z = 10 − √(4 − 1): t = 7 − √3, normal (−0.6, −0.8, −√3)/2.
        Sphere sphere = new Sphere(v(1.6, 2.8, 10), 2);
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (1,2,3) toward +z";
        assertTrue(ray + " must hit the sphere of center (1.6,2.8,10), radius 2 (at t = 7 − √3)",
                sphere.intersect(out, new Ray(v(1, 2, 3), v(0, 0, 1))));
        double root3 = Math.sqrt(3);
        assertEquals(ray + ": t", 7 - root3, out.t, TOL);
        assertVec(ray + ": location", v(1, 2, 10 - root3), out.location, TOL);
        assertVec(ray + ": normal (location − center)/radius", v(-0.3, -0.4, -root3 / 2), out.normal, TOL);
        assertSame(ray + ": out.surface must be the sphere", sphere, out.surface);
    }

    @Test
    public void nonUnitDirectionScalesT() {
        // Direction twice as long: the same point at half the t.
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray (0,0,5) + t·(0,0,−2)";
        assertTrue(ray + " must hit the unit sphere (at t = 2)", unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -2))));
        assertEquals(ray + ": the direction is not unit length, so the hit at (0,0,1) is at t = 2, not 4", 2, out.t, TOL);
        assertVec(ray + ": location", v(0, 0, 1), out.location, TOL);
        assertVec(ray + ": normal", v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void normalIsUnitLengthForALargeSphere() {
        Sphere big = new Sphere(v(0, 0, -100), 50);
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from the origin toward −z";
        assertTrue(ray + " must hit the sphere of center (0,0,−100), radius 50 (at t = 50)",
                big.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1))));
        assertEquals(ray + ": t", 50, out.t, TOL * 100);
        assertVec(ray + ": the normal must be unit length: divide by the radius", v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void sphereBehindTheRayIsMissedButHitWhenFacingIt() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse("the ray from (0,0,5) toward +z points away from the unit sphere: both roots are negative, a miss",
                unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, 1))));
        assertTrue("the ray from (0,0,5) toward −z must hit the unit sphere (at t = 4)",
                unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1))));
    }

    @Test
    public void rayPassingBesideTheSphereMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse("the ray from (0,1.5,5) toward −z passes 1.5 from the center of the unit sphere: a miss",
                unit.intersect(out, new Ray(v(0, 1.5, 5), v(0, 0, -1))));
        assertTrue("the ray from (0,0.5,5) toward −z must hit the unit sphere",
                unit.intersect(out, new Ray(v(0, 0.5, 5), v(0, 0, -1))));
        // z = √(1 − 0.25) on entry.
        assertEquals("the ray from (0,0.5,5) toward −z enters at z = √0.75", 5 - Math.sqrt(0.75), out.t, TOL);
    }

    @Test
    public void tangentRayHitsAtTheTangentPointOrMissesCleanly() {
        // (−5,1,0) + t(1,0,0) touches the unit sphere only at (0,1,0), t = 5.
        IntersectionRecord out = new IntersectionRecord();
        if (unit.intersect(out, new Ray(v(-5, 1, 0), v(1, 0, 0)))) {
            String ray = "the ray from (−5,1,0) toward +x touches the unit sphere at (0,1,0)";
            assertEquals(ray + ": t", 5, out.t, TOL);
            assertVec(ray + ": location", v(0, 1, 0), out.location, TOL);
            assertVec(ray + ": normal", v(0, 1, 0), out.normal, TOL);
        } else {
            assertEquals("a miss must leave out.t alone", Double.POSITIVE_INFINITY, out.t, 0);
        }
        // Just inside the tangent the ray hits, with finite values on the sphere.
        IntersectionRecord near = new IntersectionRecord();
        String ray = "the ray from (−5, 1 − 1e-6, 0) toward +x";
        assertTrue(ray + " must hit the unit sphere", unit.intersect(near, new Ray(v(-5, 1 - 1e-6, 0), v(1, 0, 0))));
        assertTrue(ray + ": location and normal must be finite", near.location.isFinite() && near.normal.isFinite());
        // The entry is at x = −√(1 − y²), y = 1 − 1e-6: −√(2e-6 − 1e-12).
        assertEquals(ray + ": t", 5 - Math.sqrt(2e-6 - 1e-12), near.t, 1e-12);
        assertEquals(ray + ": the location must lie on the sphere", 1, near.location.length(), 1e-15);
    }

    @Test
    public void segmentEndingBeforeTheSphereMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse("the unit sphere is first hit at t = 4, after the segment (0, 3.9) ends: a miss",
                unit.intersect(out, fromFiveDown(0, 3.9)));
        assertFalse("the end is exclusive: t = 4 is not inside the segment (0, 4), a miss",
                unit.intersect(out, fromFiveDown(0, 4)));
        assertTrue("the segment (0, 4.1) holds the hit at t = 4", unit.intersect(out, fromFiveDown(0, 4.1)));
        assertEquals("t of the hit in (0, 4.1)", 4, out.t, TOL);
    }

    @Test
    public void startBeyondNearRootReturnsFarRoot() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue("the segment (4.5, ∞) holds the far root t = 6: a hit",
                unit.intersect(out, fromFiveDown(4.5, Double.POSITIVE_INFINITY)));
        assertEquals("the near root t = 4 is before the start 4.5, so the hit is the far root", 6, out.t, TOL);
        assertVec("location of the far root", v(0, 0, -1), out.location, TOL);
        assertVec("normal at the far root (outward)", v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void startIsExclusive() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue("the segment (4, ∞) holds the far root t = 6: a hit",
                unit.intersect(out, fromFiveDown(4, Double.POSITIVE_INFINITY)));
        assertEquals("the start is exclusive: t = 4 is not in (4, ∞), so the hit is the far root", 6, out.t, TOL);
        IntersectionRecord miss = new IntersectionRecord();
        assertFalse("the segment (6, ∞) holds neither root (4 nor 6): a miss",
                unit.intersect(miss, fromFiveDown(6, Double.POSITIVE_INFINITY)));
    }

    @Test
    public void segmentBetweenTheRootsMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse("both roots (4 and 6) lie outside the segment (4.5, 5.5): a miss", unit.intersect(out, fromFiveDown(4.5, 5.5)));
        assertTrue("the segment (4.5, 6.5) holds the far root t = 6: a hit", unit.intersect(out, fromFiveDown(4.5, 6.5)));
    }

    @Test
    public void missLeavesTheRecordUntouched() {
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        IntersectionRecord before = copyOf(out);
        assertFalse("the ray from (0,0,5) toward +z must miss", unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, 1))));
        assertFalse("the segment (0, 3) ends before the hit at t = 4: a miss", unit.intersect(out, fromFiveDown(0, 3)));
        assertFalse("the ray from (0,2,5) toward −z must miss", unit.intersect(out, new Ray(v(0, 2, 5), v(0, 0, -1))));
        assertUntouched(before, out);
        // The same record is filled by a hit.
        assertTrue("the ray from (0,0,5) toward −z must hit the unit sphere (at t = 4)",
                unit.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1))));
        assertEquals("a hit must fill out.t", 4, out.t, TOL);
        assertSame("a hit must set out.surface to the sphere", unit, out.surface);
    }

    @Test
    public void rayIsNotChangedByIntersect() {
        Ray ray = fromFiveDown(0.5, 10);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue("the ray from (0,0,5) toward −z must hit the unit sphere (at t = 4)", unit.intersect(out, ray));
        assertEquals("intersect must not change ray.start", 0.5, ray.start, 0);
        assertEquals("intersect must not change ray.end", 10, ray.end, 0);
        assertVec("intersect must not change ray.origin", v(0, 0, 5), ray.origin, 0);
        assertVec("intersect must not change ray.direction", v(0, 0, -1), ray.direction, 0);
    }
}
