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

import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Checks Group.intersect, the closest-hit loop: the smallest t in (start, end) wins whatever the
 * order of the children, a tie keeps the earlier child, the caller's ray is not changed, and
 * nested groups report the primitive that was hit.
 */
public class GroupTest {
    private static final double TOL = 1e-14;
    /** Unit spheres on the −z axis; the ray t(0,0,−1) enters them at t = 4, 9 and 14. */
    private final Sphere near = new Sphere(v(0, 0, -5), 1);
    private final Sphere middle = new Sphere(v(0, 0, -10), 1);
    private final Sphere far = new Sphere(v(0, 0, -15), 1);

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
    public void closestHitWinsInEveryOrderOfTheChildren() {
        for (List<Sphere> order : permutations(List.of(near, middle, far))) {
            Group group = groupOf(order.toArray(new Surface[0]));
            IntersectionRecord out = new IntersectionRecord();
            assertTrue(order + " should hit", group.intersect(out, downZ()));
            assertEquals(order.toString(), 4, out.t, TOL);
            assertSame(order.toString(), near, out.surface);
            assertVec(v(0, 0, -4), out.location, TOL);
            assertVec(v(0, 0, 1), out.normal, TOL);
        }
    }

    @Test
    public void equalTieKeepsTheEarlierChild() {
        Sphere first = new Sphere(v(0, 0, -5), 1);
        Sphere second = new Sphere(v(0, 0, -5), 1);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(groupOf(first, second).intersect(out, downZ()));
        assertSame(first, out.surface);
        assertTrue(groupOf(second, first).intersect(out, downZ()));
        assertSame(second, out.surface);
    }

    @Test
    public void emptyGroupMissesUntilASurfaceIsAdded() {
        Group group = new Group();
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertFalse(group.intersect(out, downZ()));
        assertUntouched(before, out);
        group.addSurface(middle);
        assertTrue(group.intersect(out, downZ()));
        assertEquals(9, out.t, TOL);
    }

    @Test
    public void groupWhoseChildrenAllMissLeavesTheRecordUntouched() {
        Group group = groupOf(near, middle, far);
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertFalse(group.intersect(out, new Ray(Vec3.ZERO, v(0, 0, 1))));
        assertFalse(group.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1), 0, 3.5)));
        assertUntouched(before, out);
        assertTrue(group.intersect(out, downZ()));
    }

    @Test
    public void hitsOutsideTheRaySegmentAreIgnored() {
        Group group = groupOf(far, near, middle);
        IntersectionRecord out = new IntersectionRecord();
        // Past both roots of near (4 and 6): middle's entry at 9.
        assertTrue(group.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1), 6.5, Double.POSITIVE_INFINITY)));
        assertEquals(9, out.t, TOL);
        assertSame(middle, out.surface);
        // Between near's roots: its exit at 6, before middle's entry at 9.
        assertTrue(group.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1), 4.5, 8.5)));
        assertEquals(6, out.t, TOL);
        assertSame(near, out.surface);
        assertVec(v(0, 0, -1), out.normal, TOL);
        // Inside middle, the segment ends before its exit at 11: nothing.
        assertFalse(group.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1), 9.5, 10.5)));
        assertEquals(6, out.t, TOL);
    }

    @Test
    public void callersRayIsNotShortened() {
        Ray ray = new Ray(Vec3.ZERO, v(0, 0, -1), 0.5, 100);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(groupOf(far, middle, near).intersect(out, ray));
        assertEquals(4, out.t, TOL);
        assertEquals(0.5, ray.start, 0);
        assertEquals(100, ray.end, 0);
    }

    @Test
    public void nestedGroupsReportTheClosestPrimitive() {
        Group inner = groupOf(far, near);
        Group outer = groupOf(middle, inner);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(outer.intersect(out, downZ()));
        assertEquals(4, out.t, TOL);
        assertSame(near, out.surface);
        // The closest hit may also come before the nested group.
        Group other = groupOf(near, groupOf(far, middle));
        assertTrue(other.intersect(out, downZ()));
        assertSame(near, out.surface);
        assertEquals(4, out.t, TOL);
    }

    @Test
    public void closestHitAmongMixedPrimitives() {
        // A triangle across the axis at z = −3 (t = 3) is in front of every sphere.
        Triangle wall = new Triangle(v(-1, -1, -3), v(1, -1, -3), v(-1, 1, -3));
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(groupOf(near, wall, far).intersect(out, downZ()));
        assertEquals(3, out.t, TOL);
        assertSame(wall, out.surface);
        // (0,0) = (−1,−1) + β(2,0) + γ(0,2): β = γ = ½.
        assertEquals(0.5, out.beta, TOL);
        assertEquals(0.5, out.gamma, TOL);
    }

    @Test
    public void groupWithoutTransformIsItsOwnCompletedSurface() {
        Group group = new Group();
        group.addSurface(near);
        assertSame(group, group.complete());
        assertEquals(List.of(near), group.children());
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
