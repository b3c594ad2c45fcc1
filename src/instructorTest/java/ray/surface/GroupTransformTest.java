package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Checks groups with a transform (translate, rotate, scale, as T·Rz·Ry·Rx·S): complete() wraps
 * them, hits come back in world coordinates with the same t as in the group's own space, and
 * normals go through the inverse transpose so they stay perpendicular under non-uniform scale.
 */
public class GroupTransformTest {
    private static final double TOL = 1e-14;

    private static Surface placed(Vec3 translate, Vec3 rotate, Vec3 scale, Surface child) {
        Group group = new Group();
        group.addSurface(child);
        return Placement.of(translate, rotate, scale).place(group);
    }

    @Test
    public void translatedSphereHitInWorldCoordinates() {
        Sphere sphere = new Sphere();
        Surface moved = placed(v(1, 2, 3), Vec3.ZERO, Vec3.ONE, sphere);
        assertTrue(moved instanceof Transformed);
        // World sphere: center (1,2,3), radius 1; entered from z = 10 at z = 4.
        IntersectionRecord out = new IntersectionRecord();
        Ray ray = new Ray(v(1, 2, 10), v(0, 0, -1));
        assertTrue(moved.intersect(out, ray));
        assertEquals(6, out.t, TOL);
        assertVec(v(1, 2, 4), out.location, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
        assertSame(sphere, out.surface);
        // The segment still applies, and the caller's ray is unchanged.
        assertFalse(moved.intersect(new IntersectionRecord(), new Ray(v(1, 2, 10), v(0, 0, -1), 0, 5.5)));
        assertVec(v(1, 2, 10), ray.origin, 0);
        assertEquals(Double.POSITIVE_INFINITY, ray.end, 0);
    }

    @Test
    public void rotationAboutXTurnsTheTriangleAndItsNormal() {
        // Rx(90): (x,y,z) → (x,−z,y). The triangle (0,0,0), (1,0,0), (0,1,0) becomes (0,0,0), (1,0,0),
        // (0,0,1), with normal (1,0,0) × (0,0,1) = (0,−1,0). Point (0.25, 0, 0.5): β = 0.25, γ = 0.5.
        Triangle triangle = new Triangle(Vec3.ZERO, v(1, 0, 0), v(0, 1, 0));
        Surface turned = placed(Vec3.ZERO, v(90, 0, 0), Vec3.ONE, triangle);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(turned.intersect(out, new Ray(v(0.25, -5, 0.5), v(0, 1, 0))));
        assertEquals(5, out.t, TOL);
        assertVec(v(0.25, 0, 0.5), out.location, TOL);
        assertVec(v(0, -1, 0), out.normal, TOL);
        assertEquals(0.25, out.beta, TOL);
        assertEquals(0.5, out.gamma, TOL);
        assertSame(triangle, out.surface);
    }

    @Test
    public void rotationsApplyAboutXFirstThenZ() {
        // Rz(90)·Rx(90): (1,0,0) → (1,0,0) → (0,1,0) and (0,1,0) → (0,0,1) → (0,0,1), so the triangle
        // becomes (0,0,0), (0,1,0), (0,0,1) in the plane x = 0 with normal (1,0,0). (The other order
        // would put it in the plane y = 0, which this ray runs parallel to.)
        Triangle triangle = new Triangle(Vec3.ZERO, v(1, 0, 0), v(0, 1, 0));
        Surface turned = placed(Vec3.ZERO, v(90, 0, 90), Vec3.ONE, triangle);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(turned.intersect(out, new Ray(v(5, 0.25, 0.5), v(-1, 0, 0))));
        assertEquals(5, out.t, TOL);
        assertVec(v(0, 0.25, 0.5), out.location, TOL);
        assertVec(v(1, 0, 0), out.normal, TOL);
        assertEquals(0.25, out.beta, TOL);
        assertEquals(0.5, out.gamma, TOL);
    }

    @Test
    public void translateRotateScaleApplyScaleFirstAndTranslateLast() {
        // S(2): center (1,0,0) → (2,0,0), radius 2; Ry(90): (x,y,z) → (z,y,−x) gives (0,0,−2);
        // T(10,0,0) gives the world center (10,0,−2).
        Surface placed = placed(v(10, 0, 0), v(0, 90, 0), v(2, 2, 2), new Sphere(v(1, 0, 0), 1));
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(placed.intersect(out, new Ray(v(10, 0, 10), v(0, 0, -1))));
        assertEquals(10, out.t, TOL);
        assertVec(v(10, 0, 0), out.location, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
        assertTrue(placed.intersect(out, new Ray(v(0, 0, -2), v(1, 0, 0))));
        assertEquals(8, out.t, TOL);
        assertVec(v(8, 0, -2), out.location, TOL);
        assertVec(v(-1, 0, 0), out.normal, TOL);
    }

    @Test
    public void tIsTheSameAsForTheEquivalentWorldSphere() {
        // A unit sphere scaled by 2 about the origin is the sphere of radius 2: same t for any ray.
        Surface scaled = placed(Vec3.ZERO, Vec3.ZERO, v(2, 2, 2), new Sphere());
        Sphere world = new Sphere(Vec3.ZERO, 2);
        Random random = new Random(5);
        int hits = 0;
        for (int i = 0; i < 100; i++) {
            // From random points around the sphere toward random points of the cube [−2.5, 2.5]³.
            Vec3 origin = v(20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10);
            Vec3 target = v(5 * random.nextDouble() - 2.5, 5 * random.nextDouble() - 2.5, 5 * random.nextDouble() - 2.5);
            Ray ray = new Ray(origin, target.minus(origin).times(0.5 + random.nextDouble()));
            IntersectionRecord expected = new IntersectionRecord();
            IntersectionRecord actual = new IntersectionRecord();
            boolean hit = world.intersect(expected, ray);
            assertEquals(ray.toString(), hit, scaled.intersect(actual, ray));
            if (hit) {
                hits++;
                assertEquals(ray.toString(), expected.t, actual.t, 1e-12);
                assertVec(ray.toString(), expected.location, actual.location, 1e-12);
                assertVec(ray.toString(), expected.normal, actual.normal, 1e-12);
            }
        }
        // The rays are aimed so that most of them hit (and the comparison is not vacuous).
        assertTrue("only " + hits + " hits", hits >= 40);
    }

    @Test
    public void ellipsoidNormalComesFromTheInverseTranspose() {
        // Scale (2,1,1) of the unit sphere: x²/4 + y² + z² = 1. The ray x = 1, y = 0 down −z enters at
        // z = √(1 − 1/4) = √0.75, t = 5 − √0.75. The normal is ∝ (x/4, y, z) = (0.25, 0, √0.75)
        // (length √0.8125); mapping the local normal by the scale itself would give ∝ (1, 0, √0.75).
        Surface ellipsoid = placed(Vec3.ZERO, Vec3.ZERO, v(2, 1, 1), new Sphere());
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(ellipsoid.intersect(out, new Ray(v(1, 0, 5), v(0, 0, -1))));
        double z = Math.sqrt(0.75);
        assertEquals(5 - z, out.t, TOL);
        assertVec(v(1, 0, z), out.location, TOL);
        double len = Math.sqrt(0.8125);
        assertVec(v(0.25 / len, 0, z / len), out.normal, TOL);
    }

    @Test
    public void ellipsoidNormalsArePerpendicularToTheSurfaceForRandomRays() {
        Surface ellipsoid = placed(Vec3.ZERO, Vec3.ZERO, v(2, 1, 1), new Sphere());
        Random random = new Random(99);
        int hits = 0;
        for (int i = 0; i < 200; i++) {
            Vec3 origin = v(20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10);
            Vec3 target = v(1.6 * random.nextDouble() - 0.8, 0.8 * random.nextDouble() - 0.4, 0.8 * random.nextDouble() - 0.4);
            Ray ray = new Ray(origin, target.minus(origin));
            IntersectionRecord out = new IntersectionRecord();
            if (!ellipsoid.intersect(out, ray)) {
                continue;
            }
            hits++;
            Vec3 p = out.location;
            String what = ray + " at " + p;
            assertEquals(what, 1, p.x * p.x / 4 + p.y * p.y + p.z * p.z, 1e-12);
            assertVec(what, ray.pointAt(out.t), p, 1e-12);
            // The gradient of x²/4 + y² + z² is ∝ (x/4, y, z).
            Vec3 gradient = v(p.x / 4, p.y, p.z).normalized();
            assertVec(what, gradient, out.normal, 1e-12);
        }
        // Targets inside the ellipsoid (|x| < 0.8 < 2, |y|, |z| < 0.4) are always hit.
        assertEquals(200, hits);
    }

    @Test
    public void nestedTransformsCompose() {
        // Inner group scales the unit sphere by 2, the outer moves it to (0,0,−10): entry at z = −8.
        Surface inner = placed(Vec3.ZERO, Vec3.ZERO, v(2, 2, 2), new Sphere());
        Surface outer = placed(v(0, 0, -10), Vec3.ZERO, Vec3.ONE, inner);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(outer.intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1))));
        assertEquals(8, out.t, TOL);
        assertVec(v(0, 0, -8), out.location, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void transformedChildCompetesWithPlainSiblings() {
        // The moved sphere (entry t = 4) is in front of the plain one (entry t = 9) in either order.
        Sphere plain = new Sphere(v(0, 0, -10), 1);
        Sphere movedSphere = new Sphere();
        Surface moved = placed(v(0, 0, -5), Vec3.ZERO, Vec3.ONE, movedSphere);
        for (Surface[] order : new Surface[][] {{plain, moved}, {moved, plain}}) {
            Group group = new Group();
            for (Surface s : order) {
                group.addSurface(s);
            }
            IntersectionRecord out = new IntersectionRecord();
            assertTrue(group.complete().intersect(out, new Ray(Vec3.ZERO, v(0, 0, -1))));
            assertEquals(4, out.t, TOL);
            assertVec(v(0, 0, -4), out.location, TOL);
            assertSame(movedSphere, out.surface);
        }
    }
}
