package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.surface.HitAsserts.assertMiss;
import static ray.surface.HitAsserts.assertMissUntouched;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.util.ArrayList;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks Group.intersect, the closest-hit loop: the smallest t in (start, end) wins whatever the
 * order of the children, a tie keeps the earlier child, the caller's ray is not changed, a miss
 * leaves the record alone, and nested groups report the primitive that was hit.
 *
 * <p>The children are {@link FixedHitSurface}s, hit at a fixed t, so these tests pass with any
 * Sphere and Triangle, finished or not.
 */
@Points(1)
public class GroupTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /** Three children hit at t = 4, 9 and 14, each with its own normal. */
    private final FixedHitSurface near = new FixedHitSurface("near", 4, v(0, 0, 1));
    private final FixedHitSurface middle = new FixedHitSurface("middle", 9, v(0, 1, 0));
    private final FixedHitSurface far = new FixedHitSurface("far", 14, v(1, 0, 0));

    /** A ray along −z from the origin, segment (0, ∞). */
    private static Ray downZ() {
        return new Ray(Vec3.ZERO, v(0, 0, -1));
    }

    private static Group groupOf(Surface... children) {
        Group group = new Group();
        for (Surface child : children) {
            group.addSurface(child);
        }
        return (Group) group.complete();
    }

    @Test
    @Points(2)
    public void closestHitWinsInEveryOrderOfTheChildren() {
        for (List<Surface> order : permutations(List.<Surface>of(near, middle, far))) {
            Group group = groupOf(order.toArray(new Surface[0]));
            IntersectionRecord out = new IntersectionRecord();
            String what = "a group of " + order;
            assertHitAt(what + ", the closest hit", group, out, downZ(), 4, 0);
            assertSame(what + " must report the closest surface, near", near, out.surface);
            assertVec(what + ": location of the closest hit", v(0, 0, -4), out.location, 0);
            assertVec(what + ": normal of the closest hit", v(0, 0, 1), out.normal, 0);
        }
    }

    @Test
    @Points(2)
    public void equalTieKeepsTheEarlierChild() {
        FixedHitSurface first = new FixedHitSurface("first", 5, v(0, 0, 1));
        FixedHitSurface second = new FixedHitSurface("second", 5, v(0, 1, 0));
        IntersectionRecord out = new IntersectionRecord();
        assertHit("a group of two surfaces hit at t = 5", groupOf(first, second), out, downZ());
        assertSame("two surfaces hit at the same t: the one added first must be reported", first, out.surface);
        assertVec("the normal must be the first surface's", v(0, 0, 1), out.normal, 0);
        assertHit("a group of two surfaces hit at t = 5", groupOf(second, first), out, downZ());
        assertSame("two surfaces hit at the same t: the one added first must be reported", second, out.surface);
        assertVec("the normal must be the first surface's", v(0, 1, 0), out.normal, 0);
    }

    @Test
    public void emptyGroupMissesUntilASurfaceIsAdded() {
        Group group = new Group();
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertMiss("an empty group", group, out, downZ());
        assertUntouched(before, out);
        group.addSurface(middle);
        assertHitAt("a group holding a surface hit at t = 9", group, out, downZ(), 9, 0);
        assertSame(middle, out.surface);
    }

    @Test
    public void groupWhoseChildrenAllMissLeavesTheRecordUntouched() {
        Group group = groupOf(near, middle, far);
        IntersectionRecord out = sentinel(null);
        // The children are hit at 4, 9 and 14: none lies in (0, 3.5) or in (15, ∞).
        String rule = ": when every child misses, the group's intersect must return false and leave the record untouched";
        assertMissUntouched("children hit at t = 4, 9, 14, none inside the segment (0, 3.5)" + rule, group, out,
                new Ray(Vec3.ZERO, v(0, 0, -1), 0, 3.5));
        assertMissUntouched("children hit at t = 4, 9, 14, none inside the segment (15, ∞)" + rule, group, out,
                new Ray(Vec3.ZERO, v(0, 0, -1), 15, Double.POSITIVE_INFINITY));
        // The control: a group that never reports a hit must not pass a test of misses.
        assertHitAt("the misses were right; the control, the same group with the segment (0, ∞) that holds all three hits,"
                + " must still report the closest", group, out, downZ(), 4, 0);
    }

    @Test
    public void hitsOutsideTheRaySegmentAreIgnored() {
        Group group = groupOf(far, near, middle);
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("children hit at t = 4, 9, 14 and a ray with segment (6.5, ∞), which holds middle's and far's", group, out,
                new Ray(Vec3.ZERO, v(0, 0, -1), 6.5, Double.POSITIVE_INFINITY), 9, 0);
        assertSame("for t in (6.5, ∞) the closest hit is middle's", middle, out.surface);
        assertHit("children hit at t = 4, 9, 14 and a ray with segment (4, 14)", group, out, new Ray(Vec3.ZERO, v(0, 0, -1), 4, 14));
        assertSame("the segment (4, 14) excludes both of its ends, so only middle (t = 9) is inside", middle, out.surface);
        // (9, 14) holds none of them: both ends are excluded.
        assertMiss("children hit at t = 4, 9, 14 and a ray with segment (9, 14), which excludes both ends", group, out,
                new Ray(Vec3.ZERO, v(0, 0, -1), 9, 14));
        assertSame("a miss must leave the record alone", middle, out.surface);
    }

    @Test
    public void callersRayIsNotChanged() {
        Ray ray = new Ray(Vec3.ZERO, v(0, 0, -1), 0.5, 100);
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("children hit at t = 4, 9, 14 and a ray with segment (0.5, 100)", groupOf(far, middle, near), out, ray, 4, 0);
        assertEquals("the caller's ray.start must not change: shorten a copy of the ray", 0.5, ray.start, 0);
        assertEquals("the caller's ray.end must not change: shorten a copy of the ray", 100, ray.end, 0);
        assertVec("the caller's ray.origin must not change", Vec3.ZERO, ray.origin, 0);
        assertVec("the caller's ray.direction must not change", v(0, 0, -1), ray.direction, 0);
    }

    @Test
    @Points(2)
    public void nestedGroupsReportTheClosestPrimitive() {
        Group outer = groupOf(middle, groupOf(far, near));
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("a group holding a group, whose closest hit is inside the inner group", outer, out, downZ(), 4, 0);
        assertSame("the closest hit, near (t = 4), is inside the inner group", near, out.surface);
        // The closest hit may also come before the nested group, whose hits are all farther.
        Group other = groupOf(near, groupOf(far, middle));
        assertHitAt("a group holding a group, whose closest hit comes before the inner group", other, out, downZ(), 4, 0);
        assertSame("the closest hit, near (t = 4), comes before the inner group", near, out.surface);
    }

    @Test
    public void recordHoldsEverythingTheClosestChildReported() {
        FixedHitSurface triangleLike = new FixedHitSurface("with barycentrics", 3, v(0.6, 0, 0.8), 0.25, 0.5, 0.125, 0.875);
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("children hit at t = 4, 3, 14", groupOf(near, triangleLike, far), out, downZ(), 3, 0);
        assertSame("the closest child, hit at t = 3", triangleLike, out.surface);
        assertVec("location of the closest hit", v(0, 0, -3), out.location, 0);
        assertVec("normal of the closest hit", v(0.6, 0, 0.8), out.normal, 0);
        assertEquals("beta of the closest hit", 0.25, out.beta, 0);
        assertEquals("gamma of the closest hit", 0.5, out.gamma, 0);
        assertEquals("texU (texture coordinate) of the closest hit: copy every field, e.g. with out.set(record)", 0.125, out.texU, 0);
        assertEquals("texV (texture coordinate) of the closest hit: copy every field, e.g. with out.set(record)", 0.875, out.texV, 0);
    }

    private static <T> List<List<T>> permutations(List<T> items) {
        List<List<T>> result = new ArrayList<>();
        if (items.isEmpty()) {
            result.add(new ArrayList<>());
            return result;
        }
        for (int i = 0; i < items.size(); i++) {
            List<T> rest = new ArrayList<>(items);
            T first = rest.remove(i);
            for (List<T> tail : permutations(rest)) {
                tail.add(0, first);
                result.add(tail);
            }
        }
        return result;
    }
}
