package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;

import java.util.Random;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Triangle;

/**
 * Triangles without area ({@link DegenerateTriangles}: collinear, two vertices equal, all three equal,
 * a NaN or infinite coordinate) get the zero vector as face normal from complete() (never NaN),
 * normalAt stays finite, and they are never hit: rays aimed at points of them (and, for collinear
 * ones, rays running along their line) miss and leave the record exactly as it was, so no NaN or
 * infinity reaches it.
 * 10,000 triangles (2,500 of each kind) × 10 rays = 100,000 rays, none hit. The textbook formulas
 * do hit some (TriangleSweep, 1e6 rays per kind): of the rays at collinear triangles, Möller–Trumbore
 * reports 1.2% as hits and Cramer's rule 1.3%, with two equal vertices 0.8% and 1.1%, each hit with
 * a zero normal, since the rounded determinant of a triangle without area need not be 0.
 */
public class DegenerateTriangleTest {
    private static final int TRIANGLES = 10_000;

    @Test
    public void degenerateTrianglesHaveAZeroFaceNormalAndFiniteNormals() {
        DegenerateTriangles triangles = new DegenerateTriangles(7);
        Random random = new Random(8);
        for (int i = 0; i < TRIANGLES; i++) {
            Triangle t = triangles.next(i);
            String what = DegenerateTriangles.KINDS[triangles.kind] + " " + t;
            assertEquals(what + ": the face normal of a triangle without area", Vec3.ZERO, t.getFaceNormal());
            Vec3 n = t.normalAt(random.nextDouble(), random.nextDouble());
            assertTrue(what + ": normalAt must be finite, was " + n, n.isFinite());
        }
    }

    @Test
    public void vertexNormalsOfADegenerateTriangleNeverGiveNaN() {
        // Normals that cancel at the blend, or that are NaN themselves, fall back to the (zero) face normal.
        Vec3 p = new Vec3(1, 2, 3);
        Vec3 up = new Vec3(0, 0, 1);
        Triangle cancelling = new Triangle(p, p, p, up, up.negate(), up);
        assertEquals("β = 0.5, γ = 0: 0.5·up − 0.5·up = 0", Vec3.ZERO, cancelling.normalAt(0.5, 0));
        // A NaN normal poisons the blend everywhere, even where its weight is 0 (NaN·0 = NaN).
        Triangle broken = new Triangle(p, p, p, new Vec3(Double.NaN, 0, 1), up, up);
        assertEquals(Vec3.ZERO, broken.normalAt(0.25, 0.25));
        assertEquals(Vec3.ZERO, broken.normalAt(1, 0));
        assertEquals("NaN barycentrics", Vec3.ZERO, cancelling.normalAt(Double.NaN, 0));
    }

    @Test
    public void raysAimedAtADegenerateTriangleMissAndLeaveTheRecordUntouched() {
        DegenerateTriangles triangles = new DegenerateTriangles(7);
        Random random = new Random(9);
        int rays = 0;
        for (int i = 0; i < TRIANGLES; i++) {
            Triangle t = triangles.next(i);
            for (int k = 0; k < 10; k++) {
                Vec3 origin = new Vec3(400 * random.nextDouble() - 200, 400 * random.nextDouble() - 200, 400 * random.nextDouble() - 200);
                Ray ray = k == 0 && triangles.kind == 0
                        // Along the triangle's own line, from beyond its end: in the plane of any triangle.
                        ? new Ray(t.getV0().plus(t.getV2().minus(t.getV0()).times(-3)), t.getV2().minus(t.getV0()), -10, 10)
                        : new Ray(origin, triangles.target.minus(origin));
                assertMiss(DegenerateTriangles.KINDS[triangles.kind] + " " + t, t, ray);
                rays++;
            }
        }
        assertEquals(100_000, rays);
    }

    private static void assertMiss(String what, Triangle t, Ray ray) {
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        boolean hit;
        try {
            hit = t.intersect(out, ray);
        } catch (RuntimeException e) {
            throw new AssertionError(what + ", " + ray + ": threw " + e, e);
        }
        if (hit) {
            fail(what + " has no area, yet " + ray + " hit it at t = " + out.t + ", " + out.location);
        }
        assertUntouched(before, out);
    }
}
