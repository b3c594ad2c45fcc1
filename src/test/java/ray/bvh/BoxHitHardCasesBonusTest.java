package ray.bvh;

import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Where rounding decides: rays aimed at a box's edges and corners, near the origin and a million
 * units from it. Each ray that meets the box in exact arithmetic ({@link ExactSlabs}) must be a hit;
 * the slab test's distances are rounded three times, so an edge hit can come out a hair beyond the
 * other slab's end unless the far distance is widened by its error bound (GAMMA_3). Extra credit,
 * as the sphere's and the triangle's hard cases are.
 */
public class BoxHitHardCasesBonusTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /** Rays from random points toward random points on the box's edges: every exact hit must be a hit. */
    private static void grazeEdges(Vec3 offset, double size, long seed) {
        Random random = new Random(seed);
        Box box = new Box(offset, offset.plus(v(size, 1.5 * size, 0.75 * size)));
        for (int i = 0; i < 4000; i++) {
            // A point on one of the box's 12 edges: two coordinates at a face, the third anywhere between.
            int free = random.nextInt(3);
            double[] p = new double[3];
            for (int axis = 0; axis < 3; axis++) {
                double lo = box.min.get(axis);
                double hi = box.max.get(axis);
                p[axis] = axis == free ? lo + random.nextDouble() * (hi - lo) : random.nextBoolean() ? lo : hi;
            }
            Vec3 target = v(p[0], p[1], p[2]);
            Vec3 from = box.center().plus(v(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1)
                    .normalized().times(3 * size * (1 + random.nextDouble())));
            Ray ray = new Ray(from, target.minus(from), 0, Double.POSITIVE_INFINITY);
            if (ExactSlabs.hits(box, ray)) {
                BoxHitTest.hit(box, ray, true, " (the ray touches the box in exact arithmetic: widen the far distance by its rounding"
                        + " error, t1 · (1 + 2 GAMMA_3), so that the rounded near does not pass it)");
            }
        }
    }

    @Test
    @Points(value = 2, bonus = true)
    public void raysAimedAtAnEdgeHit() {
        grazeEdges(v(0.3, -0.7, 0.1), 1, 7001);
    }

    @Test
    @Points(value = 2, bonus = true)
    public void raysAimedAtAnEdgeFarFromTheOriginHit() {
        grazeEdges(v(1e6, -2e6, 3e6 + 0.5), 1, 7002);
    }
}
