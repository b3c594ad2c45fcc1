package ray.surface;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.util.List;
import org.junit.Test;
import ray.math.Vec3;

/**
 * Checks the framework side of Sphere, Triangle and Group, which students do not write: property
 * validation, the triangle's face normal and vertex-normal flag, and what complete() returns.
 * No intersect here (that is graded in SphereTest, TriangleTest and GroupTest).
 */
public class SurfaceSetupTest {
    @Test
    public void invalidSphereRadiusIsRejected() {
        for (double bad : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            try {
                new Sphere(Vec3.ZERO, bad);
                fail("radius " + bad + " should be rejected");
            } catch (IllegalArgumentException expected) {
                // the message names the radius
            }
        }
    }

    @Test
    public void triangleFaceNormalFollowsTheWinding() {
        // (4,0,0) × (0,2,0) = (0,0,8): +z; swapping v1 and v2 flips it.
        assertVec(v(0, 0, 1), new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2)).getFaceNormal(), 0);
        assertVec(v(0, 0, -1), new Triangle(v(0, 0, 2), v(0, 2, 2), v(4, 0, 2)).getFaceNormal(), 0);
    }

    @Test
    public void triangleBuiltWithSettersGetsItsFaceNormalFromComplete() {
        Triangle t = new Triangle();
        t.setV0(v(0, 0, 2));
        t.setV1(v(0, 2, 2));
        t.setV2(v(4, 0, 2));
        assertSame(t, t.complete());
        assertVec(v(0, 0, -1), t.getFaceNormal(), 0);
    }

    @Test
    public void vertexNormalsAreKeptOnlyWhenGiven() {
        Triangle flat = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2));
        assertFalse(TriangleFacts.hasVertexNormals(flat));
        assertEquals("a flat triangle's normal is its face normal", flat.getFaceNormal(), flat.normalAt(0.25, 0.25));
        Triangle smooth = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2), v(0, 0, 1), v(1, 0, 0), v(0, 1, 0));
        assertTrue(TriangleFacts.hasVertexNormals(smooth));
        // β = γ = 0.25: 0.5(0,0,1) + 0.25(1,0,0) + 0.25(0,1,0) = (0.25, 0.25, 0.5), length √0.375.
        double len = Math.sqrt(0.375);
        assertVec(v(0.25 / len, 0.25 / len, 0.5 / len), smooth.normalAt(0.25, 0.25), 1e-15);
    }

    @Test
    public void groupWithoutTransformIsItsOwnCompletedSurface() {
        Sphere child = new Sphere();
        Group group = new Group();
        group.addSurface(child);
        assertSame(group, group.complete());
        assertEquals(List.of(child), group.children());
    }
}
