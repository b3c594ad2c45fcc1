package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotSame;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.math.Vec3;

/**
 * The framework's description of a hit for starting new rays ({@link HitGeometry}): the hit
 * re-projected onto its sphere or onto its triangle's plane, the geometric (face) normal rather than
 * an interpolated shading normal, the scale of the numbers involved (a thin triangle's scaled up by
 * its thinness), its mapping out of a transformed group, and that a later hit never inherits the
 * geometry of an earlier one. Records are filled by hand, so no student code runs.
 */
public class HitGeometryTest {
    private static IntersectionRecord hit(Surface surface, Vec3 location, Vec3 normal) {
        IntersectionRecord out = new IntersectionRecord();
        out.t = 1;
        out.location = location;
        out.normal = normal;
        out.surface = surface;
        return out;
    }

    @Test
    public void sphereHitIsReprojectedOntoTheSphere() {
        Sphere sphere = new Sphere(v(1, 2, 3), 2);
        // 0.001 above the top (1, 2, 5), as a hit computed with a rounding error would be.
        HitGeometry g = hit(sphere, v(1, 2, 5.001), v(0, 0, 1)).geometry();
        assertVec(v(1, 2, 5), g.point, 1e-15);
        assertVec(v(0, 0, 1), g.normal, 0);
        // max|center_i| + radius = 3 + 2.
        assertEquals(5, g.scale, 0);
    }

    @Test
    public void sphereKeepsItsReportedNormalUnlessItIsNotRadial() {
        Sphere sphere = new Sphere(v(0, 0, 0), 1);
        // The reported normal leans 1e-6 off the radius through the hit; it is the one kept.
        Vec3 reported = v(0.6, 0.8, 1e-6).normalized();
        HitGeometry g = hit(sphere, v(0.6, 0.8, 0), reported).geometry();
        assertVec(reported, g.normal, 1e-16);
        assertEquals(1e-6, g.normal.z, 1e-12);
        // A normal across the radius is not this sphere's; the direction from the center replaces it.
        assertVec(v(0.6, 0.8, 0), hit(sphere, v(0.6, 0.8, 0), v(0, 0, 1)).geometry().normal, 1e-15);
    }

    @Test
    public void triangleUsesItsFaceNormalAndPlaneNotTheShadingNormal() {
        Vec3 tilted = v(1, 0, 1).normalized();
        Triangle triangle = new Triangle(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0), tilted, tilted, tilted);
        HitGeometry g = hit(triangle, v(1, 1, 0.25), tilted).geometry();
        assertVec(v(0, 0, 1), g.normal, 0);
        assertVec(v(1, 1, 0), g.point, 0);
        // Coordinates up to 4; thinness = longest edge² / |e1 × e2| = |(−4, 4, 0)|² / 16 = 32/16 = 2.
        assertEquals(8, g.scale, 0);
    }

    @Test
    public void thinTriangleScaleGrowsWithItsThinness() {
        Triangle thin = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0.5, 1e-3, 0));
        // Longest edge² = 1, |e1 × e2| = 1e-3: thinness 1000, coordinates up to 1.
        assertEquals(1000, hit(thin, v(0.5, 1e-4, 0), v(0, 0, 1)).geometry().scale, 1e-9);
        Triangle flat = new Triangle(v(0, 0, 0), v(1, 0, 0), v(2, 0, 0));
        // No area at all: the thinness is capped rather than infinite or NaN.
        assertEquals(2 * HitGeometry.MAX_THINNESS, hit(flat, v(0.5, 0, 0), v(0, 0, 1)).geometry().scale, 0);
    }

    @Test
    public void geometryLeavesATransformedGroupInWorldCoordinates() {
        // Triangle (0,0,0), (1,0,0), (0,1,1): face normal (1,0,0) × (0,1,1) = (0, −1, 1)/√2.
        Triangle triangle = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 1), v(0, 0, 1), v(0, 0, 1), v(0, 0, 1));
        Surface reportsTheTriangle = new Surface() {
            @Override
            public boolean intersect(IntersectionRecord out, Ray ray) {
                out.t = 1;
                out.location = v(0.25, 0.25, 0.25);
                out.normal = v(0, 0, 1);
                out.surface = triangle;
                return true;
            }
        };
        // Scale z by 2, then move by (10, 20, 30).
        Affine toWorld = Affine.translation(v(10, 20, 30)).after(Affine.scale(v(1, 1, 2)));
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(new Transformed(reportsTheTriangle, toWorld).intersect(out, new Ray(v(0, 0, 0), v(1, 1, 1))));
        HitGeometry g = out.geometry();
        assertVec(v(10.25, 20.25, 30.5), g.point, 1e-14);
        // World edges (1,0,0) and (0,1,2): normal (1,0,0) × (0,1,2) = (0, −2, 1)/√5.
        assertVec(v(0, -2, 1).normalized(), g.normal, 1e-15);
        // Local scale: coordinates up to 1 times thinness |(−1,1,1)|²/|(0,−1,1)| = 3/√2; then
        // ‖A‖∞ = 2 times that plus the largest translation 30.
        assertEquals(2 * 3 / Math.sqrt(2) + 30, g.scale, 1e-13);
    }

    @Test
    public void aLaterHitNeverInheritsTheGeometryOfAnEarlierOne() {
        Triangle triangle = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0));
        Surface reportsTheTriangle = new Surface() {
            @Override
            public boolean intersect(IntersectionRecord out, Ray ray) {
                out.t = 2;
                out.location = v(0.25, 0.25, 0);
                out.normal = v(0, 0, 1);
                out.surface = triangle;
                return true;
            }
        };
        IntersectionRecord out = new IntersectionRecord();
        new Transformed(reportsTheTriangle, Affine.translation(v(100, 0, 0))).intersect(out, new Ray(v(0, 0, 5), v(0, 0, -1)));
        HitGeometry fromTheGroup = out.geometry();
        // Coordinates up to 1 times thinness |(−1, 1, 0)|²/|(0, 0, 1)| = 2, plus the translation 100.
        assertEquals(102, fromTheGroup.scale, 1e-12);
        // A closer sphere, not transformed, then reports its hit into the same record, as in a group's loop.
        Sphere sphere = new Sphere(v(0, 0, 0), 3);
        out.t = 1;
        out.location = v(0, 0, 3);
        out.normal = v(0, 0, 1);
        out.surface = sphere;
        HitGeometry fromTheSphere = out.geometry();
        assertNotSame(fromTheGroup, fromTheSphere);
        assertEquals(3, fromTheSphere.scale, 0);
        assertVec(v(0, 0, 3), fromTheSphere.point, 0);
    }

    @Test
    public void setCopiesTheGeometryWithTheHit() {
        IntersectionRecord out = hit(new Sphere(v(0, 0, 0), 1), v(0, 1, 0), v(0, 1, 0));
        HitGeometry g = out.geometry();
        IntersectionRecord copy = new IntersectionRecord();
        copy.set(out);
        assertSame(g, copy.geometry());
    }
}
