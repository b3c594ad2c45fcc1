package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.v;

import java.util.HashMap;
import java.util.Map;
import org.junit.Test;
import ray.math.Vec3;

/**
 * Checks how Box builds itself: twelve triangles, two per face, whose face normals are exactly the
 * outward axes, and the corners it rejects. Hits on the box, which need working triangle and group
 * code, are checked in the instructor's BoxIntersectTest.
 */
public class BoxTest {
    /** Half-extents 1, 2, 3 about the origin (shared with the instructor's BoxIntersectTest). */
    static final Vec3 MIN = v(-1, -2, -3);
    static final Vec3 MAX = v(1, 2, 3);

    static Surface box(Vec3 min, Vec3 max) {
        Box box = new Box();
        box.setMinPt(min);
        box.setMaxPt(max);
        return box.complete();
    }

    @Test
    public void boxIsTwelveTriangles() {
        Surface box = box(MIN, MAX);
        assertTrue(box instanceof Box);
        assertEquals(12, box.children().size());
        for (Surface face : box.children()) {
            assertTrue(face instanceof Triangle);
        }
        // complete() rebuilds the faces rather than adding more.
        assertEquals(12, box.complete().children().size());
    }

    @Test
    public void eachFaceIsTwoTrianglesWithExactlyItsOutwardAxisAsNormal() {
        Map<Vec3, Integer> trianglesPerNormal = new HashMap<>();
        for (Surface child : box(MIN, MAX).children()) {
            Triangle triangle = (Triangle) child;
            Vec3 n = triangle.getFaceNormal();
            // Exact: an axis-aligned face's cross product has exact zeros, so n is ±1 on one axis.
            int axis = Math.abs(n.x) == 1 ? 0 : Math.abs(n.y) == 1 ? 1 : 2;
            assertEquals("normal " + n + " of " + triangle + " is an axis", 1, Math.abs(n.get(axis)), 0);
            assertEquals("normal " + n + " of " + triangle + " is an axis", 1, n.lengthSquared(), 0);
            // Its three vertices lie on the face that the normal points out of.
            double plane = n.get(axis) > 0 ? MAX.get(axis) : MIN.get(axis);
            for (Vec3 vertex : new Vec3[] {triangle.getV0(), triangle.getV1(), triangle.getV2()}) {
                assertEquals(triangle + " lies on its face", plane, vertex.get(axis), 0);
            }
            // + 0.0 turns −0.0 into 0.0, which Vec3.equals tells apart.
            trianglesPerNormal.merge(v(n.x + 0.0, n.y + 0.0, n.z + 0.0), 1, Integer::sum);
        }
        for (Vec3 axis : new Vec3[] {v(1, 0, 0), v(-1, 0, 0), v(0, 1, 0), v(0, -1, 0), v(0, 0, 1), v(0, 0, -1)}) {
            assertEquals("triangles with normal " + axis, Integer.valueOf(2), trianglesPerNormal.get(axis));
        }
    }

    @Test
    public void invalidCornersAreRejected() {
        assertRejected(v(0, 0, 0), v(1, 0, 1)); // flat in y
        assertRejected(v(2, 0, 0), v(1, 1, 1)); // min > max in x
        assertRejected(v(0, 0, 5), v(1, 1, 1)); // min > max in z
        assertRejected(v(0, Double.NaN, 0), v(1, 1, 1));
        assertSame(Box.class, box(Vec3.ZERO, Vec3.ONE).getClass());
    }

    private static void assertRejected(Vec3 min, Vec3 max) {
        try {
            box(min, max);
            fail("box " + min + " to " + max + " should be rejected");
        } catch (IllegalArgumentException expected) {
            // the message names both corners
        }
    }
}
