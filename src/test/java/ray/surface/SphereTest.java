package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.surface.HitAsserts.assertMiss;
import static ray.surface.HitAsserts.assertT;
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
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks Sphere.intersect on hand-computed cases: which root is returned, the exact t, location
 * and unit outward normal, the strict (start, end) segment, and that a miss leaves the record alone.
 * Each miss is paired with a nearby hit so that a sphere that never hits fails too.
 */
@Points(1)
public class SphereTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final double TOL = 1e-14;
    private final Sphere unit = new Sphere(Vec3.ZERO, 1);

    /** From (0,0,5) toward −z with the segment (start, end): it enters the unit sphere at t = 4 and leaves at t = 6. */
    private static Ray fromFiveDown(double start, double end) {
        return new Ray(v(0, 0, 5), v(0, 0, -1), start, end);
    }

    @Test
    @Points(2)
    public void hitFromOutsideReturnsNearRoot() {
        // |(0,0,5) − t(0,0,1)|² = 1 → t = 4 or 6.
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (0,0,5) toward −z";
        assertHitAt(ray + " at the unit sphere, which it enters at the nearer root", unit, out, new Ray(v(0, 0, 5), v(0, 0, -1)), 4, TOL);
        assertVec(ray + ": location", v(0, 0, 1), out.location, TOL);
        assertVec(ray + ": normal " + Hints.wordsOrFormula("the unit outward normal", "(location − center)/radius"), v(0, 0, 1), out.normal, TOL);
        assertSame(ray + ": out.surface must be the sphere", unit, out.surface);
    }

    @Test
    @Points(2)
    public void hitFromInsideReturnsFarRootWithOutwardNormal() {
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from the center (0,0,0) toward −z";
        assertHitAt(ray + " at the unit sphere, from inside (the roots are −1 and 1; only t = 1 is in (0, ∞))", unit, out,
                new Ray(Vec3.ZERO, v(0, 0, -1)), 1, TOL);
        assertVec(ray + ": location", v(0, 0, -1), out.location, TOL);
        assertVec(ray + ": the normal points outward" + Hints.fix(", (location − center)/radius,") + " even from inside",
                v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void offCenterSphereGivesHandComputedHit() {
        // Center (1.6, 2.8, 10), radius 2; ray (1,2,3) + t(0,0,1) passes at distance |(−0.6,−0.8)| = 1
        // from the center, so it enters at z = 10 − √(4 − 1): t = 7 − √3, normal (−0.6, −0.8, −√3)/2.
        Sphere sphere = new Sphere(v(1.6, 2.8, 10), 2);
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (1,2,3) toward +z";
        double root3 = Math.sqrt(3);
        assertHitAt(ray + " at the sphere of center (1.6,2.8,10), radius 2 (t = 7 − √3)", sphere, out, new Ray(v(1, 2, 3), v(0, 0, 1)),
                7 - root3, TOL);
        assertVec(ray + ": location", v(1, 2, 10 - root3), out.location, TOL);
        assertVec(ray + ": normal " + Hints.wordsOrFormula("the unit outward normal", "(location − center)/radius"),
                v(-0.3, -0.4, -root3 / 2), out.normal, TOL);
        assertSame(ray + ": out.surface must be the sphere", sphere, out.surface);
    }

    @Test
    public void nonUnitDirectionScalesT() {
        // Direction twice as long: the same point at half the t. Normalizing or not is the student's
        // choice; only t = 2 is judged, and the failure names a cause only when t shows it (HitHints).
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray (0,0,5) + t·(0,0,−2)";
        assertHitAt(ray + " at the unit sphere (|d| = 2, so the entry point (0,0,1), 4 away, is at t = 4/2)", unit, out,
                new Ray(v(0, 0, 5), v(0, 0, -2)), 2, TOL);
        assertVec(ray + ": location", v(0, 0, 1), out.location, TOL);
        assertVec(ray + ": normal", v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void normalIsUnitLengthForALargeSphere() {
        Sphere big = new Sphere(v(0, 0, -100), 50);
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from the origin toward −z";
        assertHitAt(ray + " at the sphere of center (0,0,−100), radius 50", big, out, new Ray(Vec3.ZERO, v(0, 0, -1)), 50, TOL * 100);
        assertVec(ray + ": the normal must be unit length" + Hints.fix(": divide by the radius"), v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void sphereBehindTheRayIsMissedButHitWhenFacingIt() {
        IntersectionRecord out = new IntersectionRecord();
        assertMiss("the ray from (0,0,5) toward +z points away from the unit sphere (both roots are negative)", unit, out,
                new Ray(v(0, 0, 5), v(0, 0, 1)));
        assertHit("the ray from (0,0,5) toward −z at the unit sphere", unit, out, new Ray(v(0, 0, 5), v(0, 0, -1)));
    }

    @Test
    public void rayPassingBesideTheSphereMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertMiss("the ray from (0,1.5,5) toward −z passes 1.5 from the center of the unit sphere", unit, out,
                new Ray(v(0, 1.5, 5), v(0, 0, -1)));
        // z = √(1 − 0.25) on entry.
        assertHitAt("the ray from (0,0.5,5) toward −z at the unit sphere (it enters at z = √0.75)", unit, out,
                new Ray(v(0, 0.5, 5), v(0, 0, -1)), 5 - Math.sqrt(0.75), TOL);
    }

    @Test
    public void tangentRayHitsAtTheTangentPointOrMissesCleanly() {
        // (−5,1,0) + t(1,0,0) touches the unit sphere only at (0,1,0), t = 5.
        IntersectionRecord out = new IntersectionRecord();
        Ray tangent = new Ray(v(-5, 1, 0), v(1, 0, 0));
        if (unit.intersect(out, tangent)) {
            String ray = "the ray from (−5,1,0) toward +x touches the unit sphere at (0,1,0)";
            assertT(ray, unit, out, tangent, 5, TOL);
            assertVec(ray + ": location", v(0, 1, 0), out.location, TOL);
            assertVec(ray + ": normal", v(0, 1, 0), out.normal, TOL);
        } else {
            assertEquals("a miss must leave out.t alone", Double.POSITIVE_INFINITY, out.t, 0);
        }
        // Just inside the tangent the ray hits, with finite values on the sphere.
        IntersectionRecord near = new IntersectionRecord();
        String ray = "the ray from (−5, 1 − 1e-6, 0) toward +x";
        Ray inside = new Ray(v(-5, 1 - 1e-6, 0), v(1, 0, 0));
        assertHit(ray + " at the unit sphere", unit, near, inside);
        assertTrue(ray + ": location and normal must be finite, but were " + near.location + " and " + near.normal,
                near.location.isFinite() && near.normal.isFinite());
        // The entry is at x = −√(1 − y²), y = 1 − 1e-6: −√(2e-6 − 1e-12).
        assertT(ray + " at the unit sphere", unit, near, inside, 5 - Math.sqrt(2e-6 - 1e-12), 1e-12);
        assertEquals(ray + ": the location must lie on the sphere", 1, near.location.length(), 1e-15);
    }

    @Test
    public void segmentEndingBeforeTheSphereMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertMiss("the unit sphere is first hit at t = 4, after the segment (0, 3.9) ends", unit, out, fromFiveDown(0, 3.9));
        assertMiss("the end is exclusive: t = 4 is not inside the segment (0, 4)", unit, out, fromFiveDown(0, 4));
        assertHitAt("the segment (0, 4.1) holds the hit at t = 4", unit, out, fromFiveDown(0, 4.1), 4, TOL);
    }

    @Test
    public void startBeyondNearRootReturnsFarRoot() {
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("the segment (4.5, ∞) holds the far root t = 6, and the near root t = 4 is before its start", unit, out,
                fromFiveDown(4.5, Double.POSITIVE_INFINITY), 6, TOL);
        assertVec("location of the far root", v(0, 0, -1), out.location, TOL);
        assertVec("normal at the far root (outward)", v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void startIsExclusive() {
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("the start is exclusive: t = 4 is not in the segment (4, ∞), so the hit is the far root", unit, out,
                fromFiveDown(4, Double.POSITIVE_INFINITY), 6, TOL);
        IntersectionRecord miss = new IntersectionRecord();
        assertMiss("the segment (6, ∞) holds neither root (4 nor 6)", unit, miss, fromFiveDown(6, Double.POSITIVE_INFINITY));
    }

    @Test
    public void segmentBetweenTheRootsMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertMiss("both roots (4 and 6) lie outside the segment (4.5, 5.5)", unit, out, fromFiveDown(4.5, 5.5));
        assertHit("the segment (4.5, 6.5) holds the far root t = 6", unit, out, fromFiveDown(4.5, 6.5));
    }

    @Test
    public void missLeavesTheRecordUntouched() {
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        IntersectionRecord before = copyOf(out);
        assertMiss("the ray from (0,0,5) toward +z, away from the unit sphere", unit, out, new Ray(v(0, 0, 5), v(0, 0, 1)));
        assertMiss("the segment (0, 3) ends before the hit at t = 4", unit, out, fromFiveDown(0, 3));
        assertMiss("the ray from (0,2,5) toward −z passes beside the unit sphere", unit, out, new Ray(v(0, 2, 5), v(0, 0, -1)));
        assertUntouched(before, out);
        // The same record is filled by a hit.
        assertHitAt("the ray from (0,0,5) toward −z at the unit sphere, into the record the misses left alone", unit, out,
                new Ray(v(0, 0, 5), v(0, 0, -1)), 4, TOL);
        assertSame("a hit must set out.surface to the sphere", unit, out.surface);
    }

    @Test
    public void rayIsNotChangedByIntersect() {
        Ray ray = fromFiveDown(0.5, 10);
        IntersectionRecord out = new IntersectionRecord();
        assertHit("the ray from (0,0,5) toward −z at the unit sphere", unit, out, ray);
        assertEquals("intersect must not change ray.start", 0.5, ray.start, 0);
        assertEquals("intersect must not change ray.end", 10, ray.end, 0);
        assertVec("intersect must not change ray.origin", v(0, 0, 5), ray.origin, 0);
        assertVec("intersect must not change ray.direction", v(0, 0, -1), ray.direction, 0);
    }
}
