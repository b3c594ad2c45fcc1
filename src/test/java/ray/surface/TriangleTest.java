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

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Checks Triangle.intersect on hand-computed cases: t, barycentrics, location and normal of a hit;
 * edges and vertices count as inside; rays just outside an edge, parallel rays and rays outside the
 * segment miss and leave the record alone. Each miss is paired with a nearby hit so that a triangle
 * that never hits fails too.
 */
public class TriangleTest {
    private static final double TOL = 1e-14;
    /** The right triangle (0,0,2), (4,0,2), (0,2,2) in the plane z = 2: a point is (4β, 2γ, 2). */
    private final Triangle flat = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2));

    /** A ray straight down −z onto the point (x, y) of the plane z = 2, from z = 5 (so t = 3). */
    private static Ray down(double x, double y) {
        return new Ray(v(x, y, 5), v(0, 0, -1));
    }

    @Test
    public void hitInsideGivesHandComputedValues() {
        // (1, 0.5) = (4β, 2γ) → β = γ = 0.25.
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(flat.intersect(out, down(1, 0.5)));
        assertEquals(3, out.t, TOL);
        assertVec(v(1, 0.5, 2), out.location, TOL);
        assertEquals(0.25, out.beta, TOL);
        assertEquals(0.25, out.gamma, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
        assertSame(flat, out.surface);
    }

    @Test
    public void slantedTriangleAndNonUnitDirection() {
        // Plane x + y + z = 1; the ray t(1,2,3) meets it at t = 1/6, at (1/6, 1/3, 1/2).
        // (1 − β − γ)(1,0,0) + β(0,1,0) + γ(0,0,1) = (1/6, 1/3, 1/2) → β = 1/3, γ = 1/2.
        // Normal: (−1,1,0) × (−1,0,1) = (1,1,1), normalized.
        Triangle slanted = new Triangle(v(1, 0, 0), v(0, 1, 0), v(0, 0, 1));
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(slanted.intersect(out, new Ray(Vec3.ZERO, v(1, 2, 3))));
        assertEquals(1.0 / 6, out.t, TOL);
        assertVec(v(1.0 / 6, 1.0 / 3, 0.5), out.location, TOL);
        assertEquals(1.0 / 3, out.beta, TOL);
        assertEquals(0.5, out.gamma, TOL);
        double n = 1 / Math.sqrt(3);
        assertVec(v(n, n, n), out.normal, TOL);
    }

    @Test
    public void pointsOnEdgesCountAsHits() {
        assertHit(flat, down(2, 0), 0.5, 0); // edge v0–v1, γ = 0
        assertHit(flat, down(0, 1), 0, 0.5); // edge v0–v2, β = 0
        assertHit(flat, down(2, 1), 0.5, 0.5); // edge v1–v2, β + γ = 1
    }

    @Test
    public void verticesCountAsHits() {
        assertHit(flat, down(0, 0), 0, 0);
        assertHit(flat, down(4, 0), 1, 0);
        assertHit(flat, down(0, 2), 0, 1);
    }

    @Test
    public void justOutsideEdgeV0V1Misses() {
        assertMissNextToHit(down(2, -1e-9), down(2, 1e-9));
    }

    @Test
    public void justOutsideEdgeV0V2Misses() {
        assertMissNextToHit(down(-1e-9, 1), down(1e-9, 1));
    }

    @Test
    public void justOutsideEdgeV1V2Misses() {
        assertMissNextToHit(down(2, 1 + 1e-9), down(2, 1 - 1e-9));
    }

    @Test
    public void farOutsideInEachDirectionMisses() {
        IntersectionRecord out = new IntersectionRecord();
        for (Ray ray : new Ray[] {down(5, 0.1), down(0.1, 3), down(-1, -1), down(3, 3), down(-1, 0.5), down(1, -1)}) {
            assertFalse(ray.toString(), flat.intersect(out, ray));
        }
        assertTrue(flat.intersect(out, down(0.1, 0.1)));
    }

    @Test
    public void rayParallelToThePlaneMisses() {
        assertMissNextToHit(new Ray(v(1, 0.5, 5), v(1, 0, 0)), down(1, 0.5));
    }

    @Test
    public void rayInsideThePlaneMissesWithoutNaN() {
        // The ray runs through the triangle in its own plane: the system is singular.
        assertMissNextToHit(new Ray(v(-1, 0.5, 2), v(1, 0, 0)), down(1, 0.5));
    }

    @Test
    public void triangleBehindTheRayMisses() {
        assertMissNextToHit(new Ray(v(1, 0.5, -1), v(0, 0, -1)), new Ray(v(1, 0.5, -1), v(0, 0, 1)));
    }

    @Test
    public void hitFromTheBackKeepsTheGeometricNormal() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(flat.intersect(out, new Ray(v(1, 0.5, -1), v(0, 0, 1))));
        assertEquals(3, out.t, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void segmentEndingBeforeTheHitMisses() {
        IntersectionRecord out = new IntersectionRecord();
        assertFalse(flat.intersect(out, new Ray(v(1, 0.5, 5), v(0, 0, -1), 0, 2.9)));
        // Both ends are exclusive.
        assertFalse(flat.intersect(out, new Ray(v(1, 0.5, 5), v(0, 0, -1), 0, 3)));
        assertFalse(flat.intersect(out, new Ray(v(1, 0.5, 5), v(0, 0, -1), 3, 10)));
        assertTrue(flat.intersect(out, new Ray(v(1, 0.5, 5), v(0, 0, -1), 2.9, 3.1)));
        assertEquals(3, out.t, TOL);
    }

    @Test
    public void faceNormalFollowsTheWinding() {
        assertVec(v(0, 0, 1), flat.getFaceNormal(), 0);
        Triangle reversed = new Triangle(v(0, 0, 2), v(0, 2, 2), v(4, 0, 2));
        assertVec(v(0, 0, -1), reversed.getFaceNormal(), 0);
        // The reversed winding also swaps the roles of β and γ: (2, 0.5) = 4γ, 2β.
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(reversed.intersect(out, down(2, 0.5)));
        assertVec(v(0, 0, -1), out.normal, TOL);
        assertEquals(0.25, out.beta, TOL);
        assertEquals(0.5, out.gamma, TOL);
    }

    @Test
    public void triangleBuiltWithSettersWorksAfterComplete() {
        Triangle t = new Triangle();
        t.setV0(v(0, 0, 2));
        t.setV1(v(0, 2, 2));
        t.setV2(v(4, 0, 2));
        Surface completed = t.complete();
        assertSame(t, completed);
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(completed.intersect(out, down(1, 0.5)));
        assertVec(v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void vertexNormalsAreBlendedAndNormalized() {
        Triangle smooth = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2), v(0, 0, 1), v(1, 0, 0), v(0, 1, 0));
        assertTrue(smooth.hasVertexNormals());
        IntersectionRecord out = new IntersectionRecord();
        // β = γ = 0.25: 0.5(0,0,1) + 0.25(1,0,0) + 0.25(0,1,0) = (0.25, 0.25, 0.5), length √0.375.
        assertTrue(smooth.intersect(out, down(1, 0.5)));
        double len = Math.sqrt(0.375);
        assertVec(v(0.25 / len, 0.25 / len, 0.5 / len), out.normal, TOL);
        // At a vertex the normal is that vertex's.
        assertTrue(smooth.intersect(out, down(4, 0)));
        assertVec(v(1, 0, 0), out.normal, TOL);
    }

    @Test
    public void nonUnitVertexNormalsAreBlendedBeforeNormalizing() {
        // 0.5(0,0,1) + 0.25(2,0,0) + 0.25(0,1,0) = (0.5, 0.25, 0.5), length 0.75.
        Triangle smooth = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2), v(0, 0, 1), v(2, 0, 0), v(0, 1, 0));
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(smooth.intersect(out, down(1, 0.5)));
        assertVec(v(2.0 / 3, 1.0 / 3, 2.0 / 3), out.normal, TOL);
    }

    @Test
    public void missLeavesTheRecordUntouched() {
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        IntersectionRecord before = copyOf(out);
        assertFalse(flat.intersect(out, down(5, 5)));
        assertFalse(flat.intersect(out, new Ray(v(1, 0.5, 5), v(1, 0, 0))));
        assertFalse(flat.intersect(out, new Ray(v(1, 0.5, 5), v(0, 0, -1), 0, 1)));
        assertUntouched(before, out);
        assertTrue(flat.intersect(out, down(2, 0.5)));
        assertSame(flat, out.surface);
        assertEquals(0.5, out.beta, TOL);
        assertEquals(0.25, out.gamma, TOL);
    }

    private void assertHit(Triangle triangle, Ray ray, double beta, double gamma) {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(ray + " should hit", triangle.intersect(out, ray));
        assertEquals(3, out.t, TOL);
        assertEquals("beta", beta, out.beta, TOL);
        assertEquals("gamma", gamma, out.gamma, TOL);
    }

    /** The first ray misses the flat triangle, leaving the record alone; the second, next to it, hits. */
    private void assertMissNextToHit(Ray miss, Ray hit) {
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertFalse(miss + " should miss", flat.intersect(out, miss));
        assertUntouched(before, out);
        assertTrue(hit + " should hit", flat.intersect(out, hit));
        assertTrue(out.location.isFinite() && out.normal.isFinite() && Double.isFinite(out.t));
    }
}
