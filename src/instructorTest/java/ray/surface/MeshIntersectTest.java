package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;

/**
 * Checks hits on a Mesh built from a hand-made MeshData: the unit square (0,0,0), (1,0,0), (1,1,0),
 * (0,1,0) as triangles 0-1-2 and 0-2-3, flat, with vertex normals, and with one face marked flat by
 * -1. Instructor-only: it needs working triangle and group code (MeshTest checks how the mesh is built).
 */
public class MeshIntersectTest {
    private static final double TOL = 1e-14;
    /** MeshTest's unit square: normals (0,0,1), (0.6,0,0.8), (0,0.6,0.8), all unit length. */
    private static final double[] NORMALS = MeshTest.NORMALS;

    private static Mesh mesh(double[] normals, int[] triangleNormals) {
        return MeshTest.mesh(normals, triangleNormals);
    }

    /** Straight down onto (x, y) of the square from z = 1, so t = 1. */
    private static Ray down(double x, double y) {
        return new Ray(v(x, y, 1), v(0, 0, -1));
    }

    @Test
    public void flatMeshHitsEachTriangleWithFaceNormal() {
        Mesh mesh = mesh(null, null);
        IntersectionRecord out = new IntersectionRecord();
        // Triangle 0-1-2: (0.75, 0.25) = β(1,0) + γ(1,1) → γ = 0.25, β = 0.5.
        assertTrue(mesh.intersect(out, down(0.75, 0.25)));
        assertSame(mesh.children().get(0), out.surface);
        assertEquals(1, out.t, TOL);
        assertVec(v(0.75, 0.25, 0), out.location, TOL);
        assertEquals(0.5, out.beta, TOL);
        assertEquals(0.25, out.gamma, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
        // Triangle 0-2-3: (0.25, 0.75) = β(1,1) + γ(0,1) → β = 0.25, γ = 0.5.
        assertTrue(mesh.intersect(out, down(0.25, 0.75)));
        assertSame(mesh.children().get(1), out.surface);
        assertEquals(0.25, out.beta, TOL);
        assertEquals(0.5, out.gamma, TOL);
        assertVec(v(0, 0, 1), out.normal, TOL);
        // Outside the square.
        assertFalse(mesh.intersect(out, down(1.5, 0.5)));
    }

    @Test
    public void vertexNormalsAreInterpolated() {
        // Face 0 corners use normals 0, 1, 1; face 1 corners use 0, 1, 2.
        Mesh mesh = mesh(NORMALS, new int[] {0, 1, 1, 0, 1, 2});
        IntersectionRecord out = new IntersectionRecord();
        // β = 0.5, γ = 0.25: 0.25(0,0,1) + 0.75(0.6,0,0.8) = (0.45, 0, 0.85), length √0.925.
        assertTrue(mesh.intersect(out, down(0.75, 0.25)));
        double len0 = Math.sqrt(0.925);
        assertVec(v(0.45 / len0, 0, 0.85 / len0), out.normal, TOL);
        // β = 0.25, γ = 0.5: 0.25(0,0,1) + 0.25(0.6,0,0.8) + 0.5(0,0.6,0.8) = (0.15, 0.3, 0.85), length √0.835.
        assertTrue(mesh.intersect(out, down(0.25, 0.75)));
        double len1 = Math.sqrt(0.835);
        assertVec(v(0.15 / len1, 0.3 / len1, 0.85 / len1), out.normal, TOL);
    }

    @Test
    public void faceWithNormalIndexMinusOneIsFlat() {
        Mesh mesh = mesh(NORMALS, new int[] {0, 1, 1, -1, -1, -1});
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(mesh.intersect(out, down(0.25, 0.75)));
        assertVec(v(0, 0, 1), out.normal, TOL);
        assertTrue(mesh.intersect(out, down(0.75, 0.25)));
        double len0 = Math.sqrt(0.925);
        assertVec(v(0.45 / len0, 0, 0.85 / len0), out.normal, TOL);
    }
}
