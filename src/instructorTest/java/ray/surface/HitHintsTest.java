package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * HitHints names a cause only when the returned numbers are that cause's, on hand-computed cases.
 * Only the spheres' center and radius are read: no student intersect runs here.
 */
public class HitHintsTest {
    private final Sphere unit = new Sphere(Vec3.ZERO, 1);
    /** (0,0,5) + t·(0,0,−2) enters the unit sphere at t = 2 and leaves at t = 3; |d| = 2. */
    private final Ray doubled = new Ray(v(0, 0, 5), v(0, 0, -2));

    @Test
    public void theFarRootIsNamedWhenTheReturnedTIsIt() {
        assertEquals("that is the far root, where the ray leaves the sphere, not the near one (t = 2), which is inside the"
                + " ray's segment and comes first", HitHints.forWrongT(unit, doubled, 2, 3));
    }

    @Test
    public void theNearRootIsNamedWhenTheFarOneWasExpected() {
        // From the center toward −z: the roots are −1 and 1.
        assertEquals("that is the near root, which is not inside the ray's segment (0, ∞), so the hit is the far root",
                HitHints.forWrongT(unit, new Ray(Vec3.ZERO, v(0, 0, -1)), 1, -1));
    }

    @Test
    public void aTNotRescaledAfterNormalizingIsNamed() {
        // The entry point is 4 away: t = 4 is the expected 2 times |d| = 2.
        assertEquals("that is the expected t times |d| = 2, the distance along the normalized direction: for this ray, whose"
                + " direction is not unit length, t is that distance divided by |d|", HitHints.forWrongT(unit, doubled, 2, 4));
    }

    @Test
    public void noCauseIsGuessedWhenTheNumbersShowNone() {
        assertNull(HitHints.forWrongT(unit, doubled, 2, 2.5));
        // A unit direction: t × |d| is t itself, so normalizing cannot be the cause.
        assertNull(HitHints.forWrongT(unit, new Ray(v(0, 0, 5), v(0, 0, -1)), 4, 4.5));
        assertNull(HitHints.outsideTheTriangle(0.25, 0.75));
    }

    @Test
    public void anUnexpectedHitOutsideTheSegmentOrTheTriangleIsNamed() {
        IntersectionRecord out = new IntersectionRecord();
        out.t = 4;
        assertEquals("t = 4 is not inside the ray's segment (0, 4), whose ends are both excluded",
                HitHints.forUnexpectedHit(unit, new Ray(v(0, 0, 5), v(0, 0, -1), 0, 4), out));
        assertEquals("β + γ = 1.25 > 1, so that point is outside the triangle", HitHints.outsideTheTriangle(0.5, 0.75));
        assertEquals("β = -0.5 < 0, so that point is outside the triangle", HitHints.outsideTheTriangle(-0.5, 0.75));
        assertEquals("γ = -0.25 < 0, so that point is outside the triangle", HitHints.outsideTheTriangle(0.5, -0.25));
    }
}
