package ray.math;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.surface.Cylinder;
import ray.surface.Group;
import ray.surface.Sphere;
import ray.surface.Transformed;
import ray.surface.Triangle;

/** Boxes: what they hold, and a slab test that never skips a hit, however it grazes. */
public class BoundsTest {
    private static final Bounds UNIT = new Bounds(0, 0, 0, 1, 1, 1);

    private static boolean mayHit(Bounds b, Vec3 o, Vec3 d, double start, double end) {
        return b.mayHit(o, d, start, end);
    }

    @Test
    public void aBoxHoldsItsPointsAndJoinsOthers() {
        Bounds b = Bounds.of(v(1, -2, 3), v(-1, 5, 0));
        assertEquals("Bounds[(-1.0, -2.0, 0.0) to (1.0, 5.0, 3.0)]", b.toString());
        assertEquals("Bounds[(-1.0, -2.0, 0.0) to (2.0, 5.0, 3.0)]", b.union(Bounds.of(v(2, 0, 1))).toString());
        assertTrue(Bounds.EMPTY.isEmpty());
        assertFalse(b.isEmpty());
        assertEquals(b.toString(), Bounds.EMPTY.union(b).toString());
        // A NaN coordinate: nothing can be said, so the box is everything (never skipped).
        assertEquals(Bounds.EVERYTHING, Bounds.of(v(Double.NaN, 0, 0)));
    }

    @Test
    public void primitivesAndGroupsGiveTheirBoxes() {
        Sphere sphere = new Sphere();
        sphere.setCenter(v(1, 2, 3));
        sphere.setRadius(0.5);
        assertEquals("Bounds[(0.5, 1.5, 2.5) to (1.5, 2.5, 3.5)]", sphere.bounds().toString());
        Triangle triangle = new Triangle(v(0, 0, 0), v(2, 0, 1), v(0, 3, 0));
        assertEquals("Bounds[(0.0, 0.0, 0.0) to (2.0, 3.0, 1.0)]", triangle.bounds().toString());
        Cylinder cylinder = new Cylinder();
        cylinder.setCenter(v(0, -1, 0));
        cylinder.setRadius(2);
        cylinder.setHeight(3);
        assertEquals("Bounds[(-2.0, -1.0, -2.0) to (2.0, 2.0, 2.0)]", cylinder.bounds().toString());
        Group group = new Group();
        group.addSurface(sphere);
        group.addSurface(triangle);
        assertEquals("Bounds[(0.0, 0.0, 0.0) to (2.0, 3.0, 3.5)]", group.bounds().toString());
        assertTrue(new Group().bounds().isEmpty());
    }

    @Test
    public void aPlacedGroupsBoxHoldsItsCornersMapped() {
        Triangle triangle = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0));
        // 90° about z, then up by 5: (x, y, z) ↦ (−y, x, z + 5).
        Affine m = Affine.translation(v(0, 0, 5)).after(Affine.rotation(2, 90));
        Bounds b = new Transformed(triangle, m).bounds();
        assertEquals(-1, b.minX, 1e-15);
        assertEquals(0, b.maxX, 1e-15);
        assertEquals(0, b.minY, 1e-15);
        assertEquals(1, b.maxY, 1e-15);
        assertEquals(5, b.minZ, 0);
        assertEquals(5, b.maxZ, 0);
    }

    @Test
    public void slabsSayWhereARayCanMeetTheBox() {
        Vec3 o = v(-1, 0.5, 0.5);
        assertTrue(mayHit(UNIT, o, v(1, 0, 0), 0, Double.POSITIVE_INFINITY));
        assertFalse("pointing away", mayHit(UNIT, o, v(-1, 0, 0), 0, Double.POSITIVE_INFINITY));
        assertFalse("passing above", mayHit(UNIT, v(-1, 1.5, 0.5), v(1, 0, 0), 0, Double.POSITIVE_INFINITY));
        assertFalse("ending before it", mayHit(UNIT, o, v(1, 0, 0), 0, 0.9));
        assertFalse("starting after it", mayHit(UNIT, o, v(1, 0, 0), 2.1, 5));
        assertTrue("ending exactly where it starts", mayHit(UNIT, o, v(1, 0, 0), 0, 1));
        assertTrue("starting inside", mayHit(UNIT, v(0.5, 0.5, 0.5), v(0, 0, -1), 0, 0.25));
        assertFalse("the empty box", mayHit(Bounds.EMPTY, o, v(1, 0, 0), 0, 10));
        assertTrue("everything", mayHit(Bounds.EVERYTHING, o, v(-1, 0, 0), 0, 10));
    }

    /** A flat box (a triangle in the plane z = 0) and rays that lie in its planes: never skipped. */
    @Test
    public void raysInAFacesPlaneAreNeverSkipped() {
        Bounds flat = new Bounds(0, 0, 0, 1, 1, 0);
        assertTrue("through the flat box, in its plane", mayHit(flat, v(-1, 0.5, 0), v(1, 0, 0), 0, 10));
        assertTrue("along its edge", mayHit(flat, v(-1, 0, 0), v(1, 0, 0), 0, 10));
        assertTrue("down onto it", mayHit(flat, v(0.5, 0.5, 1), v(0, 0, -1), 0, Double.POSITIVE_INFINITY));
        assertTrue("down onto its corner", mayHit(flat, v(1, 1, 1), v(0, 0, -1), 0, Double.POSITIVE_INFINITY));
        assertFalse("beside it", mayHit(flat, v(1.001, 0.5, 1), v(0, 0, -1), 0, Double.POSITIVE_INFINITY));
    }

    /**
     * The padding is relative to the coordinates: far from the origin a hit rounded an ulp outside
     * the box still counts, and a box a thousandth away is still skipped.
     */
    @Test
    public void paddingFollowsTheScaleOfTheCoordinates() {
        double x = 148376;
        Bounds far = new Bounds(x, x, x, x + 1, x + 1, x + 1);
        Vec3 above = v(x + 0.5, x + 1 + Math.ulp(x), x + 0.5);
        assertTrue(mayHit(far, above, v(1, 0, 0), 0, 10));
        assertFalse(mayHit(far, v(x + 0.5, x + 1.001, x + 0.5), v(1, 0, 0), 0, 10));
        Bounds tiny = new Bounds(1e-12, 1e-12, 1e-12, 2e-12, 2e-12, 2e-12);
        assertTrue(mayHit(tiny, v(1.5e-12, 1.5e-12, 0), v(0, 0, 1), 0, 1));
        assertFalse(mayHit(tiny, v(2.01e-12, 1.5e-12, 0), v(0, 0, 1), 0, 1));
    }
}
