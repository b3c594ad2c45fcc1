package ray.hidden;

import static org.junit.Assert.assertSame;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.surface.HitAsserts.assertMiss;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.FixedHitSurface;
import ray.surface.Group;
import ray.surface.Surface;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden group cases, all with stand-in children (no Sphere or Triangle code): a hundred children in
 * shuffled order, a hundred-way tie, deep nesting, children that compute t from the ray itself, and
 * a record that already holds a closer t.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class GroupHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static Ray downZ(double start, double end) {
        return new Ray(Vec3.ZERO, v(0, 0, -1), start, end);
    }

    private static Group groupOf(List<? extends Surface> children) {
        Group group = new Group();
        for (Surface child : children) {
            group.addSurface(child);
        }
        return (Group) group.complete();
    }

    @Test
    public void hundredShuffledChildrenReportTheClosestInTheSegment() {
        // Child k is hit at t = k + 1 (k = 0..99) with the normal (1, k, 0), in a shuffled order.
        List<FixedHitSurface> children = new ArrayList<>();
        for (int k = 0; k < 100; k++) {
            children.add(new FixedHitSurface("#" + k, k + 1, v(1, k, 0)));
        }
        List<FixedHitSurface> byT = new ArrayList<>(children);
        Collections.shuffle(children, new Random(4));
        Group group = groupOf(children);

        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("100 children hit at t = 1..100 in shuffled order, the closest hit", group, out, downZ(0, 1000), 1, 0);
        assertSame("the closest child, hit at t = 1, must be reported", byT.get(0), out.surface);
        assertVec("normal of the closest hit", v(1, 0, 0), out.normal, 0);
        assertHit("100 children hit at t = 1..100: the segment (50.5, 1000) holds 51..100", group, out, downZ(50.5, 1000));
        assertSame("in (50.5, 1000) the closest hit is at t = 51", byT.get(50), out.surface);
        assertVec("normal of the hit at t = 51", v(1, 50, 0), out.normal, 0);

        IntersectionRecord miss = sentinel(null);
        IntersectionRecord before = copyOf(miss);
        assertMiss("100 children hit at t = 1..100: nothing lies in (0, 1)", group, miss, downZ(0, 1));
        assertMiss("100 children hit at t = 1..100: nothing lies in (100, ∞)", group, miss, downZ(100, Double.POSITIVE_INFINITY));
        assertUntouched(before, miss);
    }

    @Test
    public void hundredWayTieKeepsTheFirstChild() {
        List<FixedHitSurface> children = new ArrayList<>();
        for (int k = 0; k < 100; k++) {
            children.add(new FixedHitSurface("#" + k, 7, v(0, k, 1)));
        }
        IntersectionRecord out = new IntersectionRecord();
        assertHit("100 children all hit at t = 7", groupOf(children), out, downZ(0, 10));
        assertSame("100 children all hit at t = 7: the first one added must be reported", children.get(0), out.surface);
        assertVec("the normal of the first child", v(0, 0, 1), out.normal, 0);
    }

    @Test
    public void deeplyNestedGroupsReportTheClosestPrimitive() {
        // Level k (k = 0 outermost .. 19 innermost) holds one child hit at t = 20 − k, then the next level.
        Group outermost = null;
        Group enclosing = null;
        FixedHitSurface innermostChild = null;
        for (int k = 0; k < 20; k++) {
            Group level = new Group();
            innermostChild = new FixedHitSurface("level " + k, 20 - k, v(0, 0, k));
            level.addSurface(innermostChild);
            if (enclosing == null) {
                outermost = level;
            } else {
                enclosing.addSurface(level);
            }
            enclosing = level;
        }
        IntersectionRecord out = new IntersectionRecord();
        assertHitAt("20 nested groups, whose closest hit is in the innermost", outermost, out, downZ(0, 100), 1, 0);
        assertSame("the closest hit (t = 1) is in the innermost of 20 nested groups", innermostChild, out.surface);
        // With the segment starting past it, the next level out wins.
        assertHitAt("20 nested groups with the segment (1.5, 100)", outermost, out, downZ(1.5, 100), 2, 0);
        assertVec("normal of the hit at t = 2, in level 18", v(0, 0, 18), out.normal, 0);
    }

    /** A plane z = height, hit where the ray it is given crosses it: t depends on that ray's origin and direction. */
    private static final class ZPlane extends Surface {
        final double height;

        ZPlane(double height) {
            this.height = height;
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            double t = (height - ray.origin.z) / ray.direction.z;
            if (!(ray.start < t && t < ray.end)) {
                return false;
            }
            out.t = t;
            out.location = ray.pointAt(t);
            out.normal = v(0, 0, 1);
            out.surface = this;
            return true;
        }
    }

    @Test
    public void childrenSeeTheCallersOriginAndDirection() {
        // From (0,0,5) along (0,0,−4): the plane z = −1 at t = 1.5, the plane z = −3 at t = 2.
        ZPlane lower = new ZPlane(-3);
        ZPlane upper = new ZPlane(-1);
        Group group = groupOf(List.of(lower, upper));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray (0,0,5) + t·(0,0,−4)";
        // The children must see the caller's own ray: a t that shows it was not is named by HitHints.
        assertHitAt(ray + " at planes z = −3 and z = −1, which the children compute from the ray they are given", group, out,
                new Ray(v(0, 0, 5), v(0, 0, -4)), 1.5, 0);
        assertSame(ray + " crosses z = −1 first", upper, out.surface);
        assertVec(ray + ": location", v(0, 0, -1), out.location, 0);
        assertHitAt(ray + " in the segment (1.6, 10) at z = −3", group, out, new Ray(v(0, 0, 5), v(0, 0, -4), 1.6, 10), 2, 0);
        assertSame(ray + " in the segment (1.6, 10) hits z = −3 at t = 2", lower, out.surface);
    }

    @Test
    public void hitReplacesARecordThatHoldsACloserT() {
        // Only the ray's segment limits the hits; whatever the record held before does not.
        FixedHitSurface child = new FixedHitSurface("child", 4, v(0, 0, 1));
        IntersectionRecord out = sentinel(null);
        out.t = 1;
        assertHitAt("a group with a child hit at t = 4, into a record whose t was 1 (the group's hit must replace out.t: only"
                + " ray.start and ray.end limit t)", groupOf(List.of(child)), out, downZ(0, Double.POSITIVE_INFINITY), 4, 0);
        assertSame(child, out.surface);
    }
}
