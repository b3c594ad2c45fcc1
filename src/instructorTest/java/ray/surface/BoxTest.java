package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.v;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Checks how Box builds itself: twelve triangles, two per face, whose face normals are exactly the
 * axes (outward for minPt below maxPt; for corners given the other way round on an axis, still
 * minus at minPt and plus at maxPt), the flat boxes, the warnings, and the corners it rejects.
 * Hits on the box, which need working triangle and group code, are checked in the instructor's
 * BoxIntersectTest.
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
        assertFacesOnTheirAxes(MIN, MAX);
    }

    @Test
    public void boxInvertedInYIsBuiltFromTheCornersAsGiven() {
        // MIN and MAX with y swapped: minPt.y = 2 is the top, maxPt.y = −2 the bottom.
        Vec3 min = v(-1, 2, -3);
        Vec3 max = v(1, -2, 3);
        Surface box = box(min, max);
        assertEquals(12, box.children().size());
        // Each label axis, its face's plane and the four corners the face's two triangles cover.
        // The −y face lies at minPt.y = 2, the top, and still has normal (0, −1, 0): it points into
        // the box. The +x face's first triangle, for one, is (1, 2, −3), (1, 2, 3), (1, −2, 3):
        // (0, 0, 6) × (0, −4, 6) = (0·6 − 6·(−4), 6·0 − 0·6, 0·(−4) − 0·0) = (24, 0, 0), along +x.
        assertFace(box, v(-1, 0, 0), "x = -1", v(-1, 2, -3), v(-1, 2, 3), v(-1, -2, 3), v(-1, -2, -3));
        assertFace(box, v(1, 0, 0), "x = 1", v(1, 2, -3), v(1, 2, 3), v(1, -2, 3), v(1, -2, -3));
        assertFace(box, v(0, -1, 0), "y = 2", v(-1, 2, -3), v(1, 2, -3), v(1, 2, 3), v(-1, 2, 3));
        assertFace(box, v(0, 1, 0), "y = -2", v(-1, -2, -3), v(1, -2, -3), v(1, -2, 3), v(-1, -2, 3));
        assertFace(box, v(0, 0, -1), "z = -3", v(-1, 2, -3), v(1, 2, -3), v(1, -2, -3), v(-1, -2, -3));
        assertFace(box, v(0, 0, 1), "z = 3", v(-1, 2, 3), v(1, 2, 3), v(1, -2, 3), v(-1, -2, 3));
    }

    @Test
    public void everyInversionKeepsEachFaceOnItsLabelAxis() {
        // minPt above maxPt on any set of axes: the face at minPt's coordinate has the minus axis as
        // its normal and the face at maxPt's the plus axis, whichever way that points.
        for (int inverted = 0; inverted < 8; inverted++) {
            double[] min = {MIN.x, MIN.y, MIN.z};
            double[] max = {MAX.x, MAX.y, MAX.z};
            for (int axis = 0; axis < 3; axis++) {
                if ((inverted >> axis & 1) == 1) {
                    double swap = min[axis];
                    min[axis] = max[axis];
                    max[axis] = swap;
                }
            }
            assertFacesOnTheirAxes(v(min[0], min[1], min[2]), v(max[0], max[1], max[2]));
        }
    }

    @Test
    public void flatBoxIsItsMinusFaceAlone() {
        // Flat in y at 0.5: the four side faces have no area, and the two y faces coincide; the −y
        // face alone is kept, two triangles with normal (0, −1, 0).
        Surface flat = box(v(-1, 0.5, -3), v(1, 0.5, 3));
        assertEquals(2, flat.children().size());
        assertFace(flat, v(0, -1, 0), "y = 0.5", v(-1, 0.5, -3), v(1, 0.5, -3), v(1, 0.5, 3), v(-1, 0.5, 3));
        // Also with x inverted, which turns the winding of the y faces: still (0, −1, 0).
        Surface invertedToo = box(v(1, 0.5, -3), v(-1, 0.5, 3));
        assertEquals(2, invertedToo.children().size());
        assertFace(invertedToo, v(0, -1, 0), "y = 0.5", v(-1, 0.5, -3), v(1, 0.5, -3), v(1, 0.5, 3), v(-1, 0.5, 3));
        // Flat in x at 2 (−0.0 and 0.0 count as equal too): the −x face.
        Surface flatX = box(v(2, -2, -3), v(2, 2, 3));
        assertEquals(2, flatX.children().size());
        assertFace(flatX, v(-1, 0, 0), "x = 2", v(2, -2, -3), v(2, 2, -3), v(2, 2, 3), v(2, -2, 3));
        assertEquals(2, box(v(-1, -2, -0.0), v(1, 2, 0.0)).children().size());
    }

    @Test
    public void segmentOrPointBoxHasNoTriangles() {
        IntersectionRecord out = new IntersectionRecord();
        for (Surface box : new Surface[] {box(v(0, 0, 0), v(0, 0, 1)), box(v(0, 5, 0), v(0, -5, 0)), box(v(1, 2, 3), v(1, 2, 3))}) {
            assertEquals(box.toString(), 0, box.children().size());
            assertTrue(box.toString(), box.bounds().isEmpty());
            // No triangle to ask: the framework's own search answers a miss.
            assertFalse(box.intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1))));
            assertFalse(box.intersectsAny(new Ray(v(0, 0, 5), v(0, 0, -1))));
        }
    }

    @Test
    public void nonFiniteCornersAreRejected() {
        assertRejected(v(0, Double.NaN, 0), v(1, 1, 1), "minPt is (0.0, NaN, 0.0); expected three finite numbers");
        assertRejected(v(0, 0, 0), v(1, Double.POSITIVE_INFINITY, 1), "maxPt is (1.0, Infinity, 1.0); expected three finite numbers");
        assertSame(Box.class, box(Vec3.ZERO, Vec3.ONE).getClass());
    }

    @Test
    public void warningsSayWhichAxesAreInvertedOrFlat() {
        String asGiven = "; built from the corners as given, as the course's renderer does";
        assertEquals(List.of(), ((Box) box(MIN, MAX)).warnings());
        assertEquals(List.of("Box minPt.y > maxPt.y" + asGiven), ((Box) box(v(3.0, 6.0, -12.0), v(3.1, -3.0, 3.0))).warnings());
        assertEquals(List.of("Box minPt.x > maxPt.x and minPt.y > maxPt.y" + asGiven), ((Box) box(v(2, 2, 0), v(1, 1, 1))).warnings());
        assertEquals(List.of("Box minPt.x > maxPt.x, minPt.y > maxPt.y and minPt.z > maxPt.z" + asGiven),
                ((Box) box(MAX, MIN)).warnings());
        assertEquals(List.of("Box minPt.y = maxPt.y (a flat box)" + asGiven), ((Box) box(v(0, 1, 0), v(1, 1, 1))).warnings());
        assertEquals(List.of("Box minPt.x > maxPt.x and minPt.y = maxPt.y (a flat box)" + asGiven),
                ((Box) box(v(2, 1, 0), v(1, 1, 1))).warnings());
        assertEquals(List.of("Box minPt.x = maxPt.x and minPt.y = maxPt.y (a line segment, which no ray hits); it has no faces to draw"),
                ((Box) box(v(0, 0, 0), v(0, 0, 1))).warnings());
        assertEquals(List.of("Box minPt.x = maxPt.x, minPt.y = maxPt.y and minPt.z = maxPt.z (a point, which no ray hits);"
                + " it has no faces to draw"), ((Box) box(v(1, 2, 3), v(1, 2, 3))).warnings());
    }

    @Test
    public void invertedBoxMovedToTheCameraFrameIsTheSameInvertedBox() {
        Surface moved = box(v(-1, 2, -3), v(1, -2, 3)).inFrameAt(v(10, 20, 30));
        assertSame(Box.class, moved.getClass());
        assertEquals(v(-11, -18, -33), ((Box) moved).getMinPt());
        assertEquals(v(-9, -22, -27), ((Box) moved).getMaxPt());
        assertFace(moved, v(0, -1, 0), "y = -18", v(-11, -18, -33), v(-9, -18, -33), v(-9, -18, -27), v(-11, -18, -27));
        assertFacesOnTheirAxes(v(-11, -18, -33), v(-9, -22, -27));
        // A flat box stays flat.
        assertEquals(2, box(v(-1, 0.5, -3), v(1, 0.5, 3)).inFrameAt(v(10, 20, 30)).children().size());
        // An extent of one ulp at 10⁶ that moving by 3·10⁶ would round away (4·10⁶ + 2⁻³³ is a tie,
        // rounded to the even 4·10⁶) keeps its box, placed by a translation, whichever way it is given.
        double a = 1e6;
        double b = Math.nextUp(a);
        assertTrue(box(v(a, 0, 0), v(b, 1, 1)).inFrameAt(v(-3e6, 0, 0)) instanceof Transformed);
        assertTrue(box(v(b, 0, 0), v(a, 1, 1)).inFrameAt(v(-3e6, 0, 0)) instanceof Transformed);
    }

    /**
     * Checks the box from {@code min} to {@code max} (as given, any order but not flat): two
     * triangles per normal, each normal exactly an axis, and each triangle in the plane of minPt's
     * coordinate for a minus axis and of maxPt's for a plus axis.
     */
    private static void assertFacesOnTheirAxes(Vec3 min, Vec3 max) {
        Map<Vec3, Integer> trianglesPerNormal = new HashMap<>();
        for (Surface child : box(min, max).children()) {
            Triangle triangle = (Triangle) child;
            Vec3 n = triangle.getFaceNormal();
            // Exact: an axis-aligned face's cross product has exact zeros, so n is ±1 on one axis.
            int axis = Math.abs(n.x) == 1 ? 0 : Math.abs(n.y) == 1 ? 1 : 2;
            assertEquals("normal " + n + " of " + triangle + " is an axis", 1, Math.abs(n.get(axis)), 0);
            assertEquals("normal " + n + " of " + triangle + " is an axis", 1, n.lengthSquared(), 0);
            // Its three vertices lie on the face that is labelled by the normal.
            double plane = n.get(axis) > 0 ? max.get(axis) : min.get(axis);
            for (Vec3 vertex : new Vec3[] {triangle.getV0(), triangle.getV1(), triangle.getV2()}) {
                assertEquals(triangle + " of the box " + min + " to " + max + " lies on its face", plane, vertex.get(axis), 0);
            }
            // + 0.0 turns −0.0 into 0.0, which Vec3.equals tells apart.
            trianglesPerNormal.merge(v(n.x + 0.0, n.y + 0.0, n.z + 0.0), 1, Integer::sum);
        }
        for (Vec3 axis : new Vec3[] {v(1, 0, 0), v(-1, 0, 0), v(0, 1, 0), v(0, -1, 0), v(0, 0, 1), v(0, 0, -1)}) {
            assertEquals("triangles with normal " + axis + " in the box " + min + " to " + max, Integer.valueOf(2),
                    trianglesPerNormal.get(axis));
        }
    }

    /** Checks that exactly two triangles of {@code box} have face normal {@code normal}, and that together their vertices are {@code corners}. */
    private static void assertFace(Surface box, Vec3 normal, String plane, Vec3... corners) {
        List<Triangle> face = new ArrayList<>();
        Set<Vec3> vertices = new HashSet<>();
        for (Surface child : box.children()) {
            Triangle t = (Triangle) child;
            Vec3 n = t.getFaceNormal();
            if (v(n.x + 0.0, n.y + 0.0, n.z + 0.0).equals(normal)) {
                face.add(t);
                vertices.addAll(List.of(t.getV0(), t.getV1(), t.getV2()));
            }
        }
        assertEquals("triangles with normal " + normal + " (the face at " + plane + ")", 2, face.size());
        assertEquals("corners of the face at " + plane + " with normal " + normal, Set.of(corners), vertices);
    }

    private static void assertRejected(Vec3 min, Vec3 max, String message) {
        try {
            box(min, max);
            fail("box " + min + " to " + max + " should be rejected");
        } catch (IllegalArgumentException expected) {
            assertEquals(message, expected.getMessage());
        }
    }
}
