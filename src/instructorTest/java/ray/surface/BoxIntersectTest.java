package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.util.HashSet;
import java.util.Set;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Checks hits on a Box: exactly the outward axis as the normal, the near face from outside and the
 * far face from inside, no crack along a face's diagonal, exact normals after a 90° rotation; and on
 * boxes given with minPt above maxPt on an axis (each face's normal its label axis, minus at minPt)
 * or flat (its minus face alone).
 * Instructor-only: it needs working triangle and group code (BoxTest checks how the box is built).
 */
public class BoxIntersectTest {
    private static final double TOL = 1e-14;
    /** The box of BoxTest: half-extents 1, 2, 3 about the origin. */
    private static final Vec3 MIN = BoxTest.MIN;
    private static final Vec3 MAX = BoxTest.MAX;

    private static Surface box(Vec3 min, Vec3 max) {
        return BoxTest.box(min, max);
    }

    @Test
    public void eachFaceHitFromOutsideHasExactlyItsAxisAsNormal() {
        Surface box = box(MIN, MAX);
        for (int axis = 0; axis < 3; axis++) {
            for (int sign = -1; sign <= 1; sign += 2) {
                Vec3 outward = unit(axis, sign);
                Set<Surface> trianglesHit = new HashSet<>();
                // Four points on the face, one per quadrant, so both of its triangles are hit.
                for (double[] ab : new double[][] {{0.5, 0.3}, {-0.5, 0.3}, {0.5, -0.3}, {-0.3, -0.5}}) {
                    Vec3 onFace = pointOnFace(axis, sign, ab[0], ab[1]);
                    // Start 10 outside the face, heading straight at it.
                    Ray ray = new Ray(onFace.plus(outward.times(10)), outward.negate());
                    IntersectionRecord out = new IntersectionRecord();
                    String what = "face " + outward + " at " + onFace;
                    assertTrue(what, box.intersect(out, ray));
                    assertEquals(what, 10, out.t, TOL);
                    assertVec(what, onFace, out.location, TOL);
                    // Exact: an axis-aligned face's cross product has exact zeros.
                    assertVec(what, outward, out.normal, 0);
                    trianglesHit.add(out.surface);
                }
                assertEquals("triangles hit on face " + outward, 2, trianglesHit.size());
            }
        }
    }

    @Test
    public void faceCenterOnTheSharedDiagonalIsHit() {
        // Each face's center lies on the diagonal its two triangles share: no crack there.
        Surface box = box(MIN, MAX);
        for (int axis = 0; axis < 3; axis++) {
            for (int sign = -1; sign <= 1; sign += 2) {
                Vec3 outward = unit(axis, sign);
                Vec3 center = pointOnFace(axis, sign, 0, 0);
                IntersectionRecord out = new IntersectionRecord();
                assertTrue("center of face " + outward, box.intersect(out, new Ray(center.plus(outward.times(10)), outward.negate())));
                assertEquals(10, out.t, TOL);
                assertVec(outward, out.normal, 0);
            }
        }
    }

    @Test
    public void rayFromInsideHitsTheFarFaceWithOutwardNormal() {
        Surface box = box(MIN, MAX);
        for (int axis = 0; axis < 3; axis++) {
            for (int sign = -1; sign <= 1; sign += 2) {
                Vec3 direction = unit(axis, sign);
                IntersectionRecord out = new IntersectionRecord();
                assertTrue(box.intersect(out, new Ray(v(0.1, 0.2, 0.3), direction)));
                // Distance from (0.1, 0.2, 0.3) to the face ±(1, 2, 3) along that axis.
                double expected = (axis + 1) - sign * v(0.1, 0.2, 0.3).get(axis);
                assertEquals("toward " + direction, expected, out.t, TOL);
                assertVec(direction, out.normal, 0);
            }
        }
    }

    @Test
    public void rayThroughTheBoxHitsTheNearFace() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(box(MIN, MAX).intersect(out, new Ray(v(0.5, 0.5, 10), v(0, 0, -1))));
        assertEquals(7, out.t, TOL);
        assertVec(v(0, 0, 1), out.normal, 0);
        // Once past the near face (start beyond it), the exit through −z.
        assertTrue(box(MIN, MAX).intersect(out, new Ray(v(0.5, 0.5, 10), v(0, 0, -1), 8, 100)));
        assertEquals(13, out.t, TOL);
        assertVec(v(0, 0, -1), out.normal, 0);
    }

    @Test
    public void boxRotatedBy90DegreesKeepsExactAxisNormals() {
        // Rz(90): (x,y,z) → (−y,x,z): the box spans x in [−2,2], y in [−1,1] in the world.
        Surface turned = Placement.of(Vec3.ZERO, v(0, 0, 90), Vec3.ONE).place(box(MIN, MAX));
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(turned.intersect(out, new Ray(v(10, 0.3, 0.7), v(-1, 0, 0))));
        assertEquals(8, out.t, TOL);
        assertVec(v(1, 0, 0), out.normal, 0);
        assertTrue(turned.intersect(out, new Ray(v(0.3, -10, 0.7), v(0, 1, 0))));
        assertEquals(9, out.t, TOL);
        assertVec(v(0, -1, 0), out.normal, 0);
    }

    @Test
    public void boxInvertedInYIsHitOnFacesWhoseNormalsAreTheirLabels() {
        // minPt.y = 2 above maxPt.y = −2: the face at y = 2 (the top) is the −y face, normal (0, −1, 0).
        Surface box = box(v(-1, 2, -3), v(1, -2, 3));
        IntersectionRecord out = new IntersectionRecord();
        // From (0.5, 10, 0.3) down: the top at y = 2, t = 10 − 2 = 8, normal pointing down (into the box).
        assertTrue(box.intersect(out, new Ray(v(0.5, 10, 0.3), v(0, -1, 0))));
        assertEquals(8, out.t, TOL);
        assertVec(v(0.5, 2, 0.3), out.location, TOL);
        assertVec(v(0, -1, 0), out.normal, 0);
        // From (10, 0.5, 0.3) toward −x: the face at maxPt.x = 1, t = 9, normal (+1, 0, 0) (outward, x is not inverted).
        assertTrue(box.intersect(out, new Ray(v(10, 0.5, 0.3), v(-1, 0, 0))));
        assertEquals(9, out.t, TOL);
        assertVec(v(1, 0.5, 0.3), out.location, TOL);
        assertVec(v(1, 0, 0), out.normal, 0);
        // From (0.5, −10, 0.3) up: the bottom at maxPt.y = −2, t = 8, normal (0, +1, 0) (up, into the box).
        assertTrue(box.intersect(out, new Ray(v(0.5, -10, 0.3), v(0, 1, 0))));
        assertEquals(8, out.t, TOL);
        assertVec(v(0, 1, 0), out.normal, 0);
        // From (0.5, 0.5, 10) toward −z: the face at maxPt.z = 3, t = 7, normal (0, 0, +1).
        assertTrue(box.intersect(out, new Ray(v(0.5, 0.5, 10), v(0, 0, -1))));
        assertEquals(7, out.t, TOL);
        assertVec(v(0, 0, 1), out.normal, 0);
    }

    @Test
    public void theCoursesInvertedWallIsHitOnItsTopWithNormalDown() {
        // minPt (3.0, 6.0, −12.0), maxPt (3.1, −3.0, 3.0): a wall 0.1 thick, inverted in y.
        Surface wall = box(v(3.0, 6.0, -12.0), v(3.1, -3.0, 3.0));
        IntersectionRecord out = new IntersectionRecord();
        // From (3.05, 10, 0) down: its top at y = 6, t = 4.
        assertTrue(wall.intersect(out, new Ray(v(3.05, 10, 0), v(0, -1, 0))));
        assertEquals(4, out.t, TOL);
        assertVec(v(0, -1, 0), out.normal, 0);
        // From (−10, 1, 0) toward +x: its −x face at x = 3.0, t = 13, normal (−1, 0, 0) (outward).
        assertTrue(wall.intersect(out, new Ray(v(-10, 1, 0), v(1, 0, 0))));
        assertEquals(13, out.t, TOL);
        assertVec(v(-1, 0, 0), out.normal, 0);
    }

    @Test
    public void flatBoxIsHitOnceFromEitherSideWithTheMinusNormal() {
        // Flat in y at 0.5: only its −y face is built, so it is hit once, with normal (0, −1, 0), from both sides.
        Surface flat = box(v(-1, 0.5, -3), v(1, 0.5, 3));
        IntersectionRecord out = new IntersectionRecord();
        // From (0.2, 10, 0.3) down: y = 0.5 at t = 9.5.
        assertTrue(flat.intersect(out, new Ray(v(0.2, 10, 0.3), v(0, -1, 0))));
        assertEquals(9.5, out.t, TOL);
        assertVec(v(0.2, 0.5, 0.3), out.location, TOL);
        assertVec(v(0, -1, 0), out.normal, 0);
        // Nothing more beyond it.
        assertFalse(flat.intersect(out, new Ray(v(0.2, 10, 0.3), v(0, -1, 0), 9.5 + 1e-6, Double.POSITIVE_INFINITY)));
        // From (0.2, −10, 0.3) up: y = 0.5 at t = 10.5, the same normal.
        assertTrue(flat.intersect(out, new Ray(v(0.2, -10, 0.3), v(0, 1, 0))));
        assertEquals(10.5, out.t, TOL);
        assertVec(v(0, -1, 0), out.normal, 0);
        assertFalse(flat.intersect(out, new Ray(v(0.2, -10, 0.3), v(0, 1, 0), 10.5 + 1e-6, Double.POSITIVE_INFINITY)));
        // Beside it (x = 1.5 is past maxPt.x = 1): a miss.
        assertFalse(flat.intersect(out, new Ray(v(1.5, 10, 0.3), v(0, -1, 0))));
    }

    private static Vec3 unit(int axis, int sign) {
        return axis == 0 ? v(sign, 0, 0) : axis == 1 ? v(0, sign, 0) : v(0, 0, sign);
    }

    /** The point of face (axis, sign) at fractions a, b (each in [−1, 1]) of the half-extents of the other two axes. */
    private static Vec3 pointOnFace(int axis, int sign, double a, double b) {
        double[] p = new double[3];
        p[axis] = sign > 0 ? MAX.get(axis) : MIN.get(axis);
        int first = (axis + 1) % 3;
        int second = (axis + 2) % 3;
        p[first] = a * MAX.get(first);
        p[second] = b * MAX.get(second);
        return v(p[0], p[1], p[2]);
    }
}
