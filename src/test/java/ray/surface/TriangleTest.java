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

import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTask;
import ray.testing.StudentTaskRule;

/**
 * Checks Triangle.intersect on hand-computed cases: t, barycentrics, location and normal of a hit;
 * edges and vertices count as inside; rays just outside an edge, parallel rays and rays outside the
 * segment miss and leave the record alone. Each miss is paired with a nearby hit so that a triangle
 * that never hits fails too.
 */
@Points(value = 1, task = StudentTask.TRIANGLE)
public class TriangleTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.TRIANGLE);

    private static final double TOL = 1e-14;
    /** The right triangle (0,0,2), (4,0,2), (0,2,2) in the plane z = 2: a point is (4β, 2γ, 2). */
    private final Triangle flat = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2));
    private static final String FLAT = "the triangle (0,0,2), (4,0,2), (0,2,2)";

    /** A ray straight down −z onto the point (x, y) of the plane z = 2, from z = 5 (so t = 3). */
    private static Ray down(double x, double y) {
        return new Ray(v(x, y, 5), v(0, 0, -1));
    }

    private static String downName(Ray ray) {
        return "the ray from (" + ray.origin.x + ", " + ray.origin.y + ", 5) toward −z";
    }

    @Test
    @Points(value = 2, task = StudentTask.TRIANGLE)
    public void hitInsideGivesHandComputedValues() {
        // (1, 0.5) = (4β, 2γ) → β = γ = 0.25.
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (1,0.5,5) toward −z";
        assertTrue(ray + " must hit " + FLAT + " (at t = 3)", flat.intersect(out, down(1, 0.5)));
        assertEquals(ray + ": t", 3, out.t, TOL);
        assertVec(ray + ": location", v(1, 0.5, 2), out.location, TOL);
        assertEquals(ray + ": beta (the weight of v1)", 0.25, out.beta, TOL);
        assertEquals(ray + ": gamma (the weight of v2)", 0.25, out.gamma, TOL);
        assertVec(ray + ": normal", v(0, 0, 1), out.normal, TOL);
        assertSame(ray + ": out.surface must be the triangle", flat, out.surface);
    }

    @Test
    @Points(value = 2, task = StudentTask.TRIANGLE)
    public void slantedTriangleAndNonUnitDirection() {
        // Plane x + y + z = 1; the ray t(1,2,3) meets it at t = 1/6, at (1/6, 1/3, 1/2).
        // (1 − β − γ)(1,0,0) + β(0,1,0) + γ(0,0,1) = (1/6, 1/3, 1/2) → β = 1/3, γ = 1/2.
        // Normal: (−1,1,0) × (−1,0,1) = (1,1,1), normalized.
        Triangle slanted = new Triangle(v(1, 0, 0), v(0, 1, 0), v(0, 0, 1));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray t·(1,2,3) from the origin";
        assertTrue(ray + " must hit the triangle (1,0,0), (0,1,0), (0,0,1) (at t = 1/6)",
                slanted.intersect(out, new Ray(Vec3.ZERO, v(1, 2, 3))));
        assertEquals(ray + ": t", 1.0 / 6, out.t, TOL);
        assertVec(ray + ": location", v(1.0 / 6, 1.0 / 3, 0.5), out.location, TOL);
        assertEquals(ray + ": beta", 1.0 / 3, out.beta, TOL);
        assertEquals(ray + ": gamma", 0.5, out.gamma, TOL);
        double n = 1 / Math.sqrt(3);
        assertVec(ray + ": normal", v(n, n, n), out.normal, TOL);
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
            assertFalse(downName(ray) + " passes outside " + FLAT + ": a miss", flat.intersect(out, ray));
        }
        assertTrue("the ray from (0.1,0.1,5) toward −z must hit " + FLAT, flat.intersect(out, down(0.1, 0.1)));
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
        String ray = "the ray from (1,0.5,−1) toward +z";
        assertTrue(ray + " must hit " + FLAT + " from the back (at t = 3)", flat.intersect(out, new Ray(v(1, 0.5, -1), v(0, 0, 1))));
        assertEquals(ray + ": t", 3, out.t, TOL);
        assertVec(ray + ": the normal is the geometric one, (v1 − v0) × (v2 − v0) normalized, even from the back",
                v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void segmentEndingBeforeTheHitMisses() {
        IntersectionRecord out = new IntersectionRecord();
        String hitAt3 = "the ray from (1,0.5,5) toward −z meets " + FLAT + " at t = 3";
        assertFalse(hitAt3 + ", after the segment (0, 2.9) ends: a miss", flat.intersect(out, segment(0, 2.9)));
        assertFalse(hitAt3 + ", not inside (0, 3) as the end is exclusive: a miss", flat.intersect(out, segment(0, 3)));
        assertFalse(hitAt3 + ", not inside (3, 10) as the start is exclusive: a miss", flat.intersect(out, segment(3, 10)));
        assertTrue(hitAt3 + ", inside (2.9, 3.1): a hit", flat.intersect(out, segment(2.9, 3.1)));
        assertEquals(hitAt3 + ": t", 3, out.t, TOL);
    }

    @Test
    public void reversedWindingFlipsTheNormalAndSwapsBetaAndGamma() {
        // Vertices (0,0,2), (0,2,2), (4,0,2): the normal is −z and a point is (4γ, 2β, 2), so (2, 0.5)
        // has γ = 0.5, β = 0.25.
        Triangle reversed = new Triangle(v(0, 0, 2), v(0, 2, 2), v(4, 0, 2));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (2,0.5,5) toward −z";
        assertTrue(ray + " must hit the triangle (0,0,2), (0,2,2), (4,0,2)", reversed.intersect(out, down(2, 0.5)));
        assertVec(ray + ": the normal follows the winding, (v1 − v0) × (v2 − v0) normalized", v(0, 0, -1), out.normal, TOL);
        assertEquals(ray + ": beta (the weight of v1)", 0.25, out.beta, TOL);
        assertEquals(ray + ": gamma (the weight of v2)", 0.5, out.gamma, TOL);
    }

    @Test
    public void triangleBuiltWithSettersWorksAfterComplete() {
        Triangle t = new Triangle();
        t.setV0(v(0, 0, 2));
        t.setV1(v(0, 2, 2));
        t.setV2(v(4, 0, 2));
        Surface completed = t.complete();
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (1,0.5,5) toward −z";
        assertTrue(ray + " must hit a triangle built by setV0..setV2 and complete()", completed.intersect(out, down(1, 0.5)));
        assertVec(ray + ": normal", v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void vertexNormalsAreBlendedAndNormalized() {
        Triangle smooth = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2), v(0, 0, 1), v(1, 0, 0), v(0, 1, 0));
        IntersectionRecord out = new IntersectionRecord();
        // β = γ = 0.25: 0.5(0,0,1) + 0.25(1,0,0) + 0.25(0,1,0) = (0.25, 0.25, 0.5), length √0.375.
        String ray = "the ray from (1,0.5,5) toward −z";
        assertTrue(ray + " must hit the triangle with vertex normals", smooth.intersect(out, down(1, 0.5)));
        double len = Math.sqrt(0.375);
        assertVec(ray + ": with vertex normals the normal is normalAt(beta, gamma)",
                v(0.25 / len, 0.25 / len, 0.5 / len), out.normal, TOL);
        // At a vertex the normal is that vertex's.
        assertTrue("the ray from (4,0,5) toward −z must hit the triangle at its vertex v1", smooth.intersect(out, down(4, 0)));
        assertVec("at vertex v1 the normal is v1's normal", v(1, 0, 0), out.normal, TOL);
    }

    @Test
    public void nonUnitVertexNormalsAreBlendedBeforeNormalizing() {
        // 0.5(0,0,1) + 0.25(2,0,0) + 0.25(0,1,0) = (0.5, 0.25, 0.5), length 0.75.
        Triangle smooth = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2), v(0, 0, 1), v(2, 0, 0), v(0, 1, 0));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (1,0.5,5) toward −z";
        assertTrue(ray + " must hit the triangle with vertex normals", smooth.intersect(out, down(1, 0.5)));
        assertVec(ray + ": with vertex normals the normal is normalAt(beta, gamma)", v(2.0 / 3, 1.0 / 3, 2.0 / 3), out.normal, TOL);
    }

    @Test
    public void missLeavesTheRecordUntouched() {
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        IntersectionRecord before = copyOf(out);
        assertFalse("the ray from (5,5,5) toward −z passes outside " + FLAT, flat.intersect(out, down(5, 5)));
        assertFalse("the ray from (1,0.5,5) toward +x is parallel to " + FLAT, flat.intersect(out, new Ray(v(1, 0.5, 5), v(1, 0, 0))));
        assertFalse("the segment (0, 1) ends before the hit at t = 3", flat.intersect(out, segment(0, 1)));
        assertUntouched(before, out);
        String ray = "the ray from (2,0.5,5) toward −z";
        assertTrue(ray + " must hit " + FLAT, flat.intersect(out, down(2, 0.5)));
        assertSame(ray + ": a hit must set out.surface to the triangle", flat, out.surface);
        assertEquals(ray + ": beta", 0.5, out.beta, TOL);
        assertEquals(ray + ": gamma", 0.25, out.gamma, TOL);
    }

    /** From (1, 0.5, 5) toward −z, with the segment (start, end): the flat triangle is at t = 3. */
    private static Ray segment(double start, double end) {
        return new Ray(v(1, 0.5, 5), v(0, 0, -1), start, end);
    }

    private void assertHit(Triangle triangle, Ray ray, double beta, double gamma) {
        IntersectionRecord out = new IntersectionRecord();
        String what = downName(ray);
        assertTrue(what + " must hit " + FLAT + " at t = 3 (points on edges and vertices count as inside)",
                triangle.intersect(out, ray));
        assertEquals(what + ": t", 3, out.t, TOL);
        assertEquals(what + ": beta", beta, out.beta, TOL);
        assertEquals(what + ": gamma", gamma, out.gamma, TOL);
    }

    /** The first ray misses the flat triangle, leaving the record alone; the second, next to it, hits. */
    private void assertMissNextToHit(Ray miss, Ray hit) {
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertFalse(miss + " must miss " + FLAT, flat.intersect(out, miss));
        assertUntouched(before, out);
        assertTrue(hit + " must hit " + FLAT, flat.intersect(out, hit));
        assertTrue(hit + ": t, location and normal must be finite",
                out.location.isFinite() && out.normal.isFinite() && Double.isFinite(out.t));
    }
}
