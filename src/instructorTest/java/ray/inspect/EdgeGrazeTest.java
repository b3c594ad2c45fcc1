package ray.inspect;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.util.List;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.math.Vec3;
import ray.surface.Group;
import ray.surface.Triangle;

/**
 * A miss within rounding of a triangle's edge is named as such in the trace: where two triangles
 * share that edge, both tests may round the ray outside, and the pixel is a crack the render tests
 * allow, not a mistake. Checked on the unit square split along its diagonal (0,0)–(1,1).
 */
public class EdgeGrazeTest {
    /** A triangle whose test misses every ray, as either half of a square may on its shared diagonal. */
    private static final class Missing extends Triangle {
        Missing(Vec3 a, Vec3 b, Vec3 c) {
            super(a, b, c);
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            return false;
        }
    }

    private static Ray down(double x, double y) {
        return new Ray(v(x, y, 1), v(0, 0, -1));
    }

    @Test
    public void aRayOnTheDiagonalGrazesTheEdgeFromItsFirstToItsThirdVertex() {
        Triangle lower = new Triangle(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0));
        Triangle upper = new Triangle(v(0, 0, 0), v(1, 1, 0), v(0, 1, 0));
        assertEquals("v0–v2", EdgeGraze.edge(lower, down(0.3, 0.3)));
        assertEquals("v0–v1", EdgeGraze.edge(upper, down(0.3, 0.3)));
        assertEquals("v1–v2", EdgeGraze.edge(lower, down(1, 0.5)));
    }

    @Test
    public void raysInsideOrClearlyOutsideGrazeNothing() {
        Triangle lower = new Triangle(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0));
        assertNull(EdgeGraze.edge(lower, down(0.5, 0.2)));
        assertNull("1e-6 outside is a miss, not rounding", EdgeGraze.edge(lower, down(0.3, 0.300001)));
        assertNull("behind the ray's start", EdgeGraze.edge(lower, new Ray(v(0.3, 0.3, 1), v(0, 0, 1))));
        assertNull("parallel to the plane", EdgeGraze.edge(lower, new Ray(v(0.3, 0.3, 1), v(1, 0, 0))));
    }

    @Test
    public void theSummaryOfTrianglesThatAllMissOnTheirSharedEdgeSaysItIsACrack() {
        Group square = new Group();
        square.addSurface(new Missing(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0)));
        square.addSurface(new Missing(v(0, 0, 0), v(1, 1, 0), v(0, 1, 0)));
        Ray ray = down(0.3, 0.3);
        ProbeNode node = new ProbeNode(square, false, ray, Affine.IDENTITY, 0);
        List<ProbeNode> halves = ProbeTree.of(square, ray);
        node.children.addAll(halves);
        String summary = ProbePrinter.summary(node, null);
        assertTrue(summary, summary.startsWith("2 triangles: 0 hit, 2 miss (2 of them within rounding of an edge: a test may round"));
        assertTrue(summary, summary.contains("a crack pixel the render tests allow"));
        assertEquals("v0–v2", EdgeGraze.ofMiss(halves.get(0)));
    }
}
