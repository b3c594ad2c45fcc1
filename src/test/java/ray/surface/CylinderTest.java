package ray.surface;

import static org.junit.Assert.assertSame;
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
import ray.testing.StudentTaskRule;

/**
 * Extra credit: Cylinder.intersect on hand-computed cases. Every hit is a clear margin away from
 * the rims, where the side and a cap meet and either normal would be fair, and every miss is
 * paired with a nearby hit, so a cylinder that never hits fails too.
 */
@Points(1)
public class CylinderTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final double TOL = 1e-12;
    /** Radius 1, from y = 0 to y = 2 about the y-axis. */
    private final Cylinder upright = new Cylinder(Vec3.ZERO, 1, 2);

    static void assertHit(String what, Cylinder cylinder, Ray ray, double t, Vec3 location, Vec3 normal) {
        IntersectionRecord out = new IntersectionRecord();
        String described = what + " (" + cylinder + ", the ray " + ray.origin + " + t·" + ray.direction + ")";
        HitAsserts.assertHitAt(described, cylinder, out, ray, t, TOL * Math.max(1, Math.abs(t)));
        assertVec(described + ": location", location, out.location, TOL * Math.max(1, location.maxAbs()));
        assertVec(described + ": the unit outward normal", normal, out.normal, TOL);
        assertSame(described + ": out.surface must be the cylinder", cylinder, out.surface);
    }

    static void assertMiss(String what, Cylinder cylinder, Ray ray) {
        IntersectionRecord out = sentinel(cylinder);
        IntersectionRecord before = copyOf(out);
        String described = what + " (" + cylinder + ", the ray " + ray.origin + " + t·" + ray.direction + ")";
        HitAsserts.assertMiss(described, cylinder, out, ray);
        assertUntouched(before, out);
    }

    @Test
    public void sideHitFromOutsideIsTheNearRoot() {
        // (0,1,5) toward −z meets x² + z² = 1 at z = ±1: t = 4 (enters) and 6 (leaves).
        assertHit("the side, from outside", upright, new Ray(v(0, 1, 5), v(0, 0, -1)), 4, v(0, 1, 1), v(0, 0, 1));
    }

    @Test
    public void capsAreHitWithNormalsAlongTheAxis() {
        // Straight down onto the top cap (y = 2) and straight up onto the bottom one (y = 0).
        assertHit("the top cap", upright, new Ray(v(0.5, 5, 0), v(0, -1, 0)), 3, v(0.5, 2, 0), v(0, 1, 0));
        assertHit("the bottom cap", upright, new Ray(v(0, -3, 0.5), v(0, 1, 0)), 3, v(0, 0, 0.5), v(0, -1, 0));
        // A slanted ray through the top cap: (0,4,0) + t(0.25,−1,0) reaches y = 2 at t = 2, x = 0.5.
        assertHit("the top cap, slanted", upright, new Ray(v(0, 4, 0), v(0.25, -1, 0)), 2, v(0.5, 2, 0), v(0, 1, 0));
    }

    @Test
    public void aRayFromInsideHitsTheFarWallWithTheOutwardNormal() {
        assertHit("the side, from inside", upright, new Ray(v(0, 1, 0), v(1, 0, 0)), 1, v(1, 1, 0), v(1, 0, 0));
        assertHit("the top cap, from inside", upright, new Ray(v(0, 1, 0), v(0, 1, 0)), 1, v(0, 2, 0), v(0, 1, 0));
    }

    @Test
    public void theSideCountsOnlyBetweenTheCaps() {
        // Passing above the top (y = 3 > 2) and below the bottom misses; the same ray at y = 1 hits.
        assertMiss("a ray above the top", upright, new Ray(v(0, 3, 5), v(0, 0, -1)));
        assertMiss("a ray below the bottom", upright, new Ray(v(0, -0.5, 5), v(0, 0, -1)));
        // (−3,1,0) + t(1,0.25,0) reaches x = −1 at t = 2, y = 1.5: the side, before the top cap.
        assertHit("the side, rising", upright, new Ray(v(-3, 1, 0), v(1, 0.25, 0)), 2, v(-1, 1.5, 0), v(-1, 0, 0));
    }

    @Test
    public void raysBesideOrAlongTheAxisOutsideMiss() {
        assertMiss("a ray beside the cylinder", upright, new Ray(v(3, 1, 5), v(0, 0, -1)));
        // Parallel to the axis outside the radius: no side root (a = 0) and outside both caps' discs.
        assertMiss("a ray parallel to the axis outside", upright, new Ray(v(2, -5, 0), v(0, 1, 0)));
        assertHit("a ray parallel to the axis inside", upright, new Ray(v(0.5, -5, 0.5), v(0, 1, 0)), 5, v(0.5, 0, 0.5),
                v(0, -1, 0));
    }

    @Test
    public void theSegmentStartAndEndAreStrict() {
        Vec3 origin = v(0, 1, 5);
        Vec3 down = v(0, 0, -1);
        assertMiss("the segment (0, 3.9) ends before the cylinder", upright, new Ray(origin, down, 0, 3.9));
        assertHit("the segment (4.5, ∞) starts inside: the far wall", upright, new Ray(origin, down, 4.5, Double.POSITIVE_INFINITY),
                6, v(0, 1, -1), v(0, 0, -1));
        assertMiss("the segment (6.5, ∞) starts behind the cylinder", upright, new Ray(origin, down, 6.5, Double.POSITIVE_INFINITY));
    }

    @Test
    public void anOffsetWiderCylinderAndAnUnnormalizedDirection() {
        // Center (1,2,3), radius 2, height 3. From (5,3,6) along (−4,1,−3): the xz offset from the axis
        // is (4 − 4t, 3 − 3t), of length 5(1 − t) = 2 at t = 0.6, where y = 3.6 is between 2 and 5.
        Cylinder offset = new Cylinder(v(1, 2, 3), 2, 3);
        assertHit("the side of an offset cylinder", offset, new Ray(v(5, 3, 6), v(-4, 1, -3)), 0.6, v(2.6, 3.6, 4.2),
                v(0.8, 0, 0.6));
        // The same ray with its direction scaled by 10: the same point at t/10.
        assertHit("the same ray, direction ×10", offset, new Ray(v(5, 3, 6), v(-40, 10, -30)), 0.06, v(2.6, 3.6, 4.2),
                v(0.8, 0, 0.6));
        // Down onto its top cap at y = 5, and its bottom at y = 2 from below.
        assertHit("the offset cylinder's top", offset, new Ray(v(1.5, 12, 3.5), v(0, -2, 0)), 3.5, v(1.5, 5, 3.5), v(0, 1, 0));
        assertHit("the offset cylinder's bottom", offset, new Ray(v(0, -1, 2), v(0, 1, 0)), 3, v(0, 2, 2), v(0, -1, 0));
    }

    @Test
    public void aMissLeavesTheRecordAlone() {
        IntersectionRecord out = sentinel(upright);
        IntersectionRecord before = copyOf(out);
        HitAsserts.assertMiss("the ray (3,1,5) toward −z passes beside the cylinder", upright, out, new Ray(v(3, 1, 5), v(0, 0, -1)));
        assertUntouched(before, out);
        HitAsserts.assertHit("the ray (0,1,5) toward −z at the cylinder", upright, out, new Ray(v(0, 1, 5), v(0, 0, -1)));
    }
}
