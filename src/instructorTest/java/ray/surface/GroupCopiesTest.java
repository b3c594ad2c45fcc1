package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import java.util.List;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.SearchCounter;
import ray.math.Vec3;
import ray.shading.Lambertian;
import ray.shading.Shader;

/**
 * The copies the framework makes of a group (moved to the camera's frame, counted for a renderer
 * thread) are new groups of the student's class over the copied parts: they search with the
 * student's loop, keep the group's shader, and start from none of the original's state.
 */
public class GroupCopiesTest {
    /** A student's group that caches its parts in an array at its first search, as an optimization. */
    public static final class CachingGroup extends Group {
        private Surface[] cached;

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            if (cached == null) {
                cached = surfaces.toArray(new Surface[0]);
            }
            Ray closestSoFar = ray.copy();
            boolean hitAny = false;
            for (Surface surface : cached) {
                if (surface.intersect(out, closestSoFar)) {
                    closestSoFar.end = out.t;
                    hitAny = true;
                }
            }
            return hitAny;
        }
    }

    @Test
    public void aMovedGroupSearchesItsMovedPartsEvenIfItCachedTheOriginals() {
        CachingGroup group = new CachingGroup();
        Shader shader = new Lambertian();
        group.setShader(shader);
        group.addSurface(new Sphere(new Vec3(1000, 0, 0), 1).complete());
        // A search before the copy fills the cache with the sphere at x = 1000.
        assertTrue(group.intersect(new IntersectionRecord(), new Ray(new Vec3(1000, 0, 5), new Vec3(0, 0, -1))));

        Surface moved = group.inFrameAt(new Vec3(1000, 0, 0));
        assertSame(CachingGroup.class, moved.getClass());
        assertSame(shader, moved.getShader());
        IntersectionRecord out = new IntersectionRecord();
        // In the frame at (1000, 0, 0) the sphere is at the origin: hit at z = 1, t = 4.
        assertTrue(moved.intersect(out, new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1))));
        assertEquals(4, out.t, 0);
        assertFalse("the original sphere, 1000 away, is not in the moved frame",
                moved.intersect(new IntersectionRecord(), new Ray(new Vec3(1000, 0, 5), new Vec3(0, 0, -1))));
    }

    @Test
    public void aCountedGroupCountsEachPartsTestWithTheStudentsLoop() {
        CachingGroup group = new CachingGroup();
        group.addSurface(new Sphere(new Vec3(0, 0, 0), 1).complete());
        group.addSurface(new Sphere(new Vec3(0, 0, -5), 1).complete());
        group.intersect(new IntersectionRecord(), new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1)));
        SearchCounter counter = new SearchCounter();
        Surface counted = group.searchCopy(Acceleration.BVH, counter);
        assertSame(CachingGroup.class, counted.getClass());
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(counted.intersect(out, new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1))));
        assertEquals(4, out.t, 0);
        assertEquals("one test per sphere, through the copy's own parts", 2, counter.tests(SearchCounter.CAMERA));
        // A shadow ray stops at the first part it hits.
        assertTrue(counted.intersectsAny(new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1))));
        assertEquals(3, counter.tests(SearchCounter.CAMERA));
    }

    @Test
    public void aGroupThatCannotBeMadeAnewIsCopiedAsAnyOtherSurface() {
        Group anonymous = new Group() {
        };
        anonymous.addSurface(new Sphere(new Vec3(0, 0, 0), 1).complete());
        assertTrue(anonymous.inFrameAt(new Vec3(1, 0, 0)) instanceof Transformed);
        Surface counted = anonymous.searchCopy(Acceleration.BVH, new SearchCounter());
        assertEquals(List.of(anonymous), counted.children());
    }

    @Test
    public void anEmptyGroupHoldsNothingAndIsNoPrimitive() {
        Group empty = new Group();
        assertTrue(empty.bounds().isEmpty());
        assertFalse(empty.isPrimitive());
        assertTrue(new Sphere(new Vec3(0, 0, 0), 1).isPrimitive());
    }
}
