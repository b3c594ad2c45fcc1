package ray.surface;

import static org.junit.Assert.assertEquals;
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
 * its thinness), and its mapping out of transforms ({@link Placements}), on the path that hit. Records are filled by hand, so no student code runs.
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

    /** The geometry of a hit on a primitive that no transform places. */
    private static HitGeometry geometry(IntersectionRecord hit) {
        return hit.surface.hitGeometry(hit);
    }

    @Test
    public void sphereHitIsReprojectedOntoTheSphere() {
        Sphere sphere = new Sphere(v(1, 2, 3), 2);
        // 0.001 above the top (1, 2, 5), as a hit computed with a rounding error would be.
        HitGeometry g = geometry(hit(sphere, v(1, 2, 5.001), v(0, 0, 1)));
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
        HitGeometry g = geometry(hit(sphere, v(0.6, 0.8, 0), reported));
        assertVec(reported, g.normal, 1e-16);
        assertEquals(1e-6, g.normal.z, 1e-12);
        // A normal across the radius is not this sphere's; the direction from the center replaces it.
        assertVec(v(0.6, 0.8, 0), geometry(hit(sphere, v(0.6, 0.8, 0), v(0, 0, 1))).normal, 1e-15);
    }

    @Test
    public void triangleUsesItsFaceNormalAndPlaneNotTheShadingNormal() {
        Vec3 tilted = v(1, 0, 1).normalized();
        Triangle triangle = new Triangle(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0), tilted, tilted, tilted);
        HitGeometry g = geometry(hit(triangle, v(1, 1, 0.25), tilted));
        assertVec(v(0, 0, 1), g.normal, 0);
        assertVec(v(1, 1, 0), g.point, 0);
        // Coordinates up to 4; thinness = longest edge² / |e1 × e2| = |(−4, 4, 0)|² / 16 = 32/16 = 2.
        assertEquals(8, g.scale, 0);
    }

    @Test
    public void thinTriangleScaleGrowsWithItsThinness() {
        Triangle thin = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0.5, 1e-3, 0));
        // Longest edge² = 1, |e1 × e2| = 1e-3: thinness 1000, coordinates up to 1.
        assertEquals(1000, geometry(hit(thin, v(0.5, 1e-4, 0), v(0, 0, 1))).scale, 1e-9);
        Triangle flat = new Triangle(v(0, 0, 0), v(1, 0, 0), v(2, 0, 0));
        // No area at all: the thinness is capped rather than infinite or NaN.
        assertEquals(2 * HitGeometry.MAX_THINNESS, geometry(hit(flat, v(0.5, 0, 0), v(0, 0, 1))).scale, 0);
    }

    /** A triangle, hit wherever a ray comes from at {@code local} (in its own coordinates) with normal +z. */
    private static TriangleSurface fixedHitTriangle(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 local) {
        return new TriangleSurface(v0, v1, v2, v(0, 0, 1), v(0, 0, 1), v(0, 0, 1)) {
            @Override
            public boolean intersect(IntersectionRecord out, Ray ray) {
                out.t = 1;
                out.location = local;
                out.normal = v(0, 0, 1);
                out.surface = this;
                return true;
            }
        };
    }

    @Test
    public void geometryOfATransformedHitIsMadeInThePrimitivesCoordinatesAndMappedOut() {
        // Triangle (0,0,0), (1,0,0), (0,1,1): face normal (1,0,0) × (0,1,1) = (0, −1, 1)/√2.
        TriangleSurface triangle = fixedHitTriangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 1), v(0.25, 0.25, 0.25));
        // Scale z by 2, then move by (10, 20, 30).
        Affine toWorld = Affine.translation(v(10, 20, 30)).after(Affine.scale(v(1, 1, 2)));
        Surface placed = new Transformed(triangle, toWorld);
        IntersectionRecord out = new IntersectionRecord();
        // A ray toward the hit's world point (the placed triangle's box is tested before the triangle).
        assertTrue(placed.intersect(out, new Ray(v(0, 0, 0), v(10.25, 20.25, 30.5))));
        assertVec("the record's location is mapped out", v(10.25, 20.25, 30.5), out.location, 1e-14);
        HitGeometry g = Placements.of(placed).geometryOf(out);
        assertVec(v(10.25, 20.25, 30.5), g.point, 1e-14);
        assertSame("the reported location is kept as it is", out.location, g.location);
        // World edges (1,0,0) and (0,1,2): normal (1,0,0) × (0,1,2) = (0, −2, 1)/√5.
        assertVec(v(0, -2, 1).normalized(), g.normal, 1e-15);
        // Local scale: coordinates up to 1 times thinness |(−1,1,1)|²/|(0,−1,1)| = 3/√2; then
        // ‖A‖∞ = 2 times that plus the largest translation 30.
        assertEquals(2 * 3 / Math.sqrt(2) + 30, g.scale, 1e-13);
    }

    @Test
    public void aHitOutsideEveryTransformIsMeasuredAsReported() {
        Sphere sphere = new Sphere(v(0, 0, 0), 3);
        Group root = new Group();
        root.addSurface(new Transformed(new Sphere(v(0, 0, 0), 1), Affine.translation(v(100, 0, 0))));
        root.addSurface(sphere);
        HitGeometry g = Placements.of(root).geometryOf(hit(sphere, v(0, 0, 3), v(0, 0, 1)));
        assertEquals(3, g.scale, 0);
        assertVec(v(0, 0, 3), g.point, 0);
    }

    @Test
    public void aPrimitiveReusedUnderTwoTransformsIsMeasuredOnThePathThatHit() {
        // One triangle placed twice, at x + 100 and at x − 100 (a named group used twice).
        TriangleSurface triangle = fixedHitTriangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0), v(0.25, 0.25, 0));
        Group root = new Group();
        root.addSurface(new Transformed(triangle, Affine.translation(v(100, 0, 0))));
        root.addSurface(new Transformed(triangle, Affine.translation(v(-100, 0, 0))));
        Placements placements = Placements.of(root);
        HitGeometry right = placements.geometryOf(hit(triangle, v(100.25, 0.25, 0), v(0, 0, 1)));
        HitGeometry left = placements.geometryOf(hit(triangle, v(-99.75, 0.25, 0), v(0, 0, 1)));
        assertVec(v(100.25, 0.25, 0), right.point, 1e-13);
        assertVec(v(-99.75, 0.25, 0), left.point, 1e-13);
    }

    @Test
    public void setCopiesEveryFieldOfTheHit() {
        IntersectionRecord out = hit(new Sphere(v(0, 0, 0), 1), v(0, 1, 0), v(0, 1, 0));
        out.beta = 0.25;
        out.gamma = 0.5;
        IntersectionRecord copy = new IntersectionRecord();
        copy.set(out);
        assertEquals(out.toString(), copy.toString());
        assertEquals(0.25, copy.beta, 0);
        assertEquals(0.5, copy.gamma, 0);
        assertSame(out.surface, copy.surface);
    }
}
