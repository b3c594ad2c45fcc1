package ray.surface;

import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.surface.HitAsserts.assertBarycentrics;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.surface.HitAsserts.assertMiss;
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
import ray.testing.StudentTaskRule;

/**
 * Checks Triangle.intersect on hand-computed cases: t, barycentrics, location and normal of a hit;
 * edges and vertices count as inside; rays just outside an edge, parallel rays and rays outside the
 * segment miss and leave the record alone. Each miss is paired with a nearby hit so that a triangle
 * that never hits fails too.
 */
@Points(1)
public class TriangleTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

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
    @Points(2)
    public void hitInsideGivesHandComputedValues() {
        // (1, 0.5) = (4β, 2γ) → β = γ = 0.25.
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (1,0.5,5) toward −z";
        assertHitAt(ray + " at " + FLAT + " (β is the weight of v1, γ of v2)", flat, out, down(1, 0.5), 3, TOL, 0.25, 0.25, TOL);
        assertVec(ray + ": location", v(1, 0.5, 2), out.location, TOL);
        assertVec(ray + ": normal", v(0, 0, 1), out.normal, TOL);
        assertSame(ray + ": out.surface must be the triangle", flat, out.surface);
    }

    @Test
    @Points(2)
    public void slantedTriangleAndNonUnitDirection() {
        // Plane x + y + z = 1; the ray t(1,2,3) meets it at t = 1/6, at (1/6, 1/3, 1/2).
        // (1 − β − γ)(1,0,0) + β(0,1,0) + γ(0,0,1) = (1/6, 1/3, 1/2) → β = 1/3, γ = 1/2.
        // Normal: (−1,1,0) × (−1,0,1) = (1,1,1), normalized.
        Triangle slanted = new Triangle(v(1, 0, 0), v(0, 1, 0), v(0, 0, 1));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray t·(1,2,3) from the origin";
        assertHitAt(ray + " at the triangle (1,0,0), (0,1,0), (0,0,1) (t = 1/6, β = 1/3, γ = 1/2)", slanted, out,
                new Ray(Vec3.ZERO, v(1, 2, 3)), 1.0 / 6, TOL, 1.0 / 3, 0.5, TOL);
        assertVec(ray + ": location", v(1.0 / 6, 1.0 / 3, 0.5), out.location, TOL);
        double n = 1 / Math.sqrt(3);
        assertVec(ray + ": normal", v(n, n, n), out.normal, TOL);
    }

    @Test
    public void pointsOnEdgesCountAsHits() {
        assertEdgeHit(flat, down(2, 0), 0.5, 0); // edge v0–v1, γ = 0
        assertEdgeHit(flat, down(0, 1), 0, 0.5); // edge v0–v2, β = 0
        assertEdgeHit(flat, down(2, 1), 0.5, 0.5); // edge v1–v2, β + γ = 1
    }

    @Test
    public void verticesCountAsHits() {
        assertEdgeHit(flat, down(0, 0), 0, 0);
        assertEdgeHit(flat, down(4, 0), 1, 0);
        assertEdgeHit(flat, down(0, 2), 0, 1);
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
            assertMiss(downName(ray) + " passes outside " + FLAT, flat, out, ray);
        }
        assertHit("the ray from (0.1,0.1,5) toward −z at " + FLAT, flat, out, down(0.1, 0.1));
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
        assertHitAt(ray + " at " + FLAT + ", from the back", flat, out, new Ray(v(1, 0.5, -1), v(0, 0, 1)), 3, TOL);
        assertVec(ray + ": the normal is the geometric one, (v1 − v0) × (v2 − v0) normalized, even from the back",
                v(0, 0, 1), out.normal, TOL);
    }

    @Test
    public void segmentEndingBeforeTheHitMisses() {
        IntersectionRecord out = new IntersectionRecord();
        String hitAt3 = "the ray from (1,0.5,5) toward −z meets " + FLAT + " at t = 3";
        assertMiss(hitAt3 + ", after the segment (0, 2.9) ends", flat, out, segment(0, 2.9));
        assertMiss(hitAt3 + ", not inside (0, 3) as the end is exclusive", flat, out, segment(0, 3));
        assertMiss(hitAt3 + ", not inside (3, 10) as the start is exclusive", flat, out, segment(3, 10));
        assertHitAt(hitAt3 + ", inside (2.9, 3.1)", flat, out, segment(2.9, 3.1), 3, TOL);
    }

    @Test
    public void reversedWindingFlipsTheNormalAndSwapsBetaAndGamma() {
        // Vertices (0,0,2), (0,2,2), (4,0,2): the normal is −z and a point is (4γ, 2β, 2), so (2, 0.5)
        // has γ = 0.5, β = 0.25.
        Triangle reversed = new Triangle(v(0, 0, 2), v(0, 2, 2), v(4, 0, 2));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (2,0.5,5) toward −z";
        assertHit(ray + " at the triangle (0,0,2), (0,2,2), (4,0,2)", reversed, out, down(2, 0.5));
        assertVec(ray + ": the normal follows the winding, (v1 − v0) × (v2 − v0) normalized", v(0, 0, -1), out.normal, TOL);
        assertBarycentrics(ray + " at the reversed triangle (β is the weight of v1, γ of v2)", out, 0.25, 0.5, TOL);
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
        assertHit(ray + " at a triangle built by setV0..setV2 and complete()", completed, out, down(1, 0.5));
        assertVec(ray + ": normal", v(0, 0, -1), out.normal, TOL);
    }

    @Test
    public void vertexNormalsAreBlendedAndNormalized() {
        Triangle smooth = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2), v(0, 0, 1), v(1, 0, 0), v(0, 1, 0));
        IntersectionRecord out = new IntersectionRecord();
        // β = γ = 0.25: 0.5(0,0,1) + 0.25(1,0,0) + 0.25(0,1,0) = (0.25, 0.25, 0.5), length √0.375.
        String ray = "the ray from (1,0.5,5) toward −z";
        assertHit(ray + " at the triangle with vertex normals", smooth, out, down(1, 0.5));
        double len = Math.sqrt(0.375);
        assertVec(ray + ": with vertex normals the normal is normalAt(beta, gamma)",
                v(0.25 / len, 0.25 / len, 0.5 / len), out.normal, TOL);
        // At a vertex the normal is that vertex's.
        assertHit("the ray from (4,0,5) toward −z at the triangle's vertex v1", smooth, out, down(4, 0));
        assertVec("at vertex v1 the normal is v1's normal", v(1, 0, 0), out.normal, TOL);
    }

    @Test
    public void nonUnitVertexNormalsAreBlendedBeforeNormalizing() {
        // 0.5(0,0,1) + 0.25(2,0,0) + 0.25(0,1,0) = (0.5, 0.25, 0.5), length 0.75.
        Triangle smooth = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2), v(0, 0, 1), v(2, 0, 0), v(0, 1, 0));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray from (1,0.5,5) toward −z";
        assertHit(ray + " at the triangle with vertex normals", smooth, out, down(1, 0.5));
        assertVec(ray + ": with vertex normals the normal is normalAt(beta, gamma)", v(2.0 / 3, 1.0 / 3, 2.0 / 3), out.normal, TOL);
    }

    @Test
    public void missLeavesTheRecordUntouched() {
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        IntersectionRecord before = copyOf(out);
        assertMiss("the ray from (5,5,5) toward −z passes outside " + FLAT, flat, out, down(5, 5));
        assertMiss("the ray from (1,0.5,5) toward +x is parallel to " + FLAT, flat, out, new Ray(v(1, 0.5, 5), v(1, 0, 0)));
        assertMiss("the segment (0, 1) ends before the hit at t = 3", flat, out, segment(0, 1));
        assertUntouched(before, out);
        String ray = "the ray from (2,0.5,5) toward −z";
        assertHit(ray + " at " + FLAT + ", into the record the misses left alone", flat, out, down(2, 0.5));
        assertSame(ray + ": a hit must set out.surface to the triangle", flat, out.surface);
        assertBarycentrics(ray + " at " + FLAT, out, 0.5, 0.25, TOL);
    }

    /** From (1, 0.5, 5) toward −z, with the segment (start, end): the flat triangle is at t = 3. */
    private static Ray segment(double start, double end) {
        return new Ray(v(1, 0.5, 5), v(0, 0, -1), start, end);
    }

    private void assertEdgeHit(Triangle triangle, Ray ray, double beta, double gamma) {
        assertHitAt(downName(ray) + " at " + FLAT + " (points on edges and vertices count as inside)", triangle,
                new IntersectionRecord(), ray, 3, TOL, beta, gamma, TOL);
    }

    /** The first ray misses the flat triangle, leaving the record alone; the second, next to it, hits. */
    private void assertMissNextToHit(Ray miss, Ray hit) {
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertMiss(miss + " at " + FLAT, flat, out, miss);
        assertUntouched(before, out);
        assertHit(hit + " at " + FLAT + ", next to the miss", flat, out, hit);
        assertTrue(hit + ": t, location and normal must be finite; " + HitMessages.returned(out, true) + ", location "
                + out.location + ", normal " + out.normal,
                out.location.isFinite() && out.normal.isFinite() && Double.isFinite(out.t));
    }
}
