package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;

/**
 * Checks how Mesh builds its triangles from a hand-made MeshData: the unit square (0,0,0), (1,0,0),
 * (1,1,0), (0,1,0) as triangles 0-1-2 and 0-2-3, flat, with vertex normals, and with one face marked
 * flat by -1. Hits on the mesh, which need working triangle and group code, are checked in the
 * instructor's MeshIntersectTest.
 */
public class MeshTest {
    private static final double TOL = 1e-14;
    static final double[] SQUARE = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    static final int[] TRIANGLES = {0, 1, 2, 0, 2, 3};
    /** Normals (0,0,1), (0.6,0,0.8), (0,0.6,0.8): all unit length. */
    static final double[] NORMALS = {0, 0, 1, 0.6, 0, 0.8, 0, 0.6, 0.8};

    /** The unit square as two triangles (shared with the instructor's MeshIntersectTest). */
    static Mesh mesh(double[] normals, int[] triangleNormals) {
        Mesh mesh = new Mesh();
        mesh.setData(new MeshData(SQUARE, normals, TRIANGLES, triangleNormals));
        assertSame(mesh, mesh.complete());
        return mesh;
    }

    @Test
    public void meshHasOneTrianglePerFaceSharingVertices() {
        Mesh mesh = mesh(null, null);
        assertEquals(2, mesh.getData().triangleCount());
        assertEquals(4, mesh.getData().vertexCount());
        assertEquals(2, mesh.children().size());
        Triangle first = (Triangle) mesh.children().get(0);
        Triangle second = (Triangle) mesh.children().get(1);
        // Triangles 0-1-2 and 0-2-3 share the vertex objects 0 and 2.
        assertSame(first.getV0(), second.getV0());
        assertSame(first.getV2(), second.getV1());
        // complete() again rebuilds rather than adding.
        mesh.complete();
        assertEquals(2, mesh.children().size());
    }

    @Test
    public void vertexNormalsGoToTheTrianglesThatUseThem() {
        // Face 0 corners use normals 0, 1, 1; face 1 corners use 0, 1, 2.
        Mesh mesh = mesh(NORMALS, new int[] {0, 1, 1, 0, 1, 2});
        Triangle first = (Triangle) mesh.children().get(0);
        Triangle second = (Triangle) mesh.children().get(1);
        assertTrue(TriangleFacts.hasVertexNormals(first));
        assertTrue(TriangleFacts.hasVertexNormals(second));
        // At a vertex the blend is that vertex's normal: face 1's v1 (β = 1) and v2 (γ = 1) use normals 1 and 2.
        assertVec(v(0.6, 0, 0.8), second.normalAt(1, 0), TOL);
        assertVec(v(0, 0.6, 0.8), second.normalAt(0, 1), TOL);
        assertVec(v(0, 0, 1), first.normalAt(0, 0), TOL);
    }

    @Test
    public void faceWithNormalIndexMinusOneIsFlat() {
        Mesh mesh = mesh(NORMALS, new int[] {0, 1, 1, -1, -1, -1});
        assertTrue(TriangleFacts.hasVertexNormals((Triangle) mesh.children().get(0)));
        Triangle flat = (Triangle) mesh.children().get(1);
        assertFalse(TriangleFacts.hasVertexNormals(flat));
        assertVec(v(0, 0, 1), flat.normalAt(0.25, 0.5), 0);
    }

    @Test
    public void meshWithoutDataIsRejected() {
        try {
            new Mesh().complete();
            fail("a mesh without data should be rejected");
        } catch (IllegalArgumentException expected) {
            // the message asks for <data>
        }
    }
}
