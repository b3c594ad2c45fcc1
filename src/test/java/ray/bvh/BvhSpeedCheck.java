package ray.bvh;

import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.util.Locale;
import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.Timeout;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Bvh;
import ray.accel.BvhBuilder;
import ray.accel.SearchCounter;
import ray.math.Vec3;

/**
 * How fast is fast enough: 81,920 small squares over a sphere (the size of the course's largest
 * meshes), searched by your tree, the framework's and the plain loop, with the same rays in one run,
 * so the machine's speed cancels out of the ratios. It passes when your search takes at most 3 times
 * the framework's and is at least 20 times faster than the plain loop. Each is timed at its best of
 * several rounds, taken in turn, so a busy moment falls on all of them alike; the plain loop, which
 * tests every square, is timed on fewer rays and compared per ray.
 *
 * <p>Feedback, not graded: the grader never runs your code in the process that keeps the score, so
 * it cannot time your search beside the framework's on equal terms. Run it with
 * {@code gradle test --tests ray.bvh.BvhSpeedCheck}.
 */
public class BvhSpeedCheck {
    @Rule
    public final Timeout limit = Timeout.seconds(300);

    private static final int SQUARES = 81_920;
    private static final int RAYS = 4_000;
    private static final int LINEAR_RAYS = 100;
    private static final int ROUNDS = 5;

    /** Squares over the sphere of radius 1 about the origin, each facing the axis nearest its normal. */
    private static Squares.Square[] sphereOfSquares(Random random) {
        Squares.Square[] squares = new Squares.Square[SQUARES];
        for (int i = 0; i < SQUARES; i++) {
            Vec3 n;
            do {
                n = new Vec3(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1);
            } while (n.lengthSquared() > 1 || n.lengthSquared() < 1e-6);
            n = n.normalized();
            int axis = Math.abs(n.x) >= Math.abs(n.y) && Math.abs(n.x) >= Math.abs(n.z) ? 0 : Math.abs(n.y) >= Math.abs(n.z) ? 1 : 2;
            squares[i] = new Squares.Square(i, axis, n, 0.008);
        }
        return squares;
    }

    /** Camera rays from (0, 0, 4) toward random points of the sphere's disk. */
    private static Ray[] rays(Random random, int count) {
        Ray[] rays = new Ray[count];
        Vec3 eye = new Vec3(0, 0, 4);
        for (int i = 0; i < count; i++) {
            Vec3 target = new Vec3(2.2 * random.nextDouble() - 1.1, 2.2 * random.nextDouble() - 1.1, 0);
            rays[i] = new Ray(eye, target.minus(eye).normalized(), 1e-9, Double.POSITIVE_INFINITY);
        }
        return rays;
    }

    private interface Search {
        boolean closest(IntersectionRecord out, Ray ray);
    }

    /** Seconds per ray of the search over the rays, and a checksum of what it found so the work is not optimized away. */
    private static double perRay(Search search, Ray[] rays, int count, double[] checksum) {
        IntersectionRecord out = new IntersectionRecord();
        long start = System.nanoTime();
        double sum = 0;
        for (int i = 0; i < count; i++) {
            if (search.closest(out, rays[i].copy())) {
                sum += out.t;
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        checksum[0] += sum;
        return seconds / count;
    }

    @Test
    public void yourTreeIsWithinThreeTimesTheFrameworksAndTwentyTimesFasterThanTheLoop() {
        Random random = new Random(4620_2019);
        Squares.Square[] squares = sphereOfSquares(random);
        Ray[] rays = rays(random, RAYS);
        Box[] boxes = Squares.boxes(squares);
        BvhTree yours = new BvhTree();
        yours.prepare(squares, boxes);
        long buildStart = System.nanoTime();
        BvhNode root = yours.build(0, SQUARES);
        double buildSeconds = (System.nanoTime() - buildStart) / 1e9;
        assertNull("Your build over " + SQUARES + " squares: " + TreeInvariants.firstProblem(root, yours, boxes),
                TreeInvariants.firstProblem(root, yours, boxes));
        Bvh framework = BvhBuilder.build(squares, true);
        SearchCounter counter = new SearchCounter();
        Search yourSearch = (out, ray) -> yours.closestHit(root, out, ray);
        Search frameworkSearch = (out, ray) -> framework.closestHit(out, ray, counter);
        Search loop = (out, ray) -> {
            IntersectionRecord best = Squares.linear(squares, ray);
            if (best != null) {
                out.set(best);
            }
            return best != null;
        };
        double[] checksum = new double[1];
        double you = Double.POSITIVE_INFINITY;
        double them = Double.POSITIVE_INFINITY;
        double linear = Double.POSITIVE_INFINITY;
        for (int round = 0; round < ROUNDS; round++) {
            you = Math.min(you, perRay(yourSearch, rays, RAYS, checksum));
            them = Math.min(them, perRay(frameworkSearch, rays, RAYS, checksum));
            if (round < 2) {
                linear = Math.min(linear, perRay(loop, rays, LINEAR_RAYS, checksum));
            }
        }
        yours.resetCounts();
        perRay(yourSearch, rays, RAYS, checksum);
        String report = String.format(Locale.ROOT, "Over %,d squares: your search %.2f µs a ray (built in %.0f ms; %.1f boxes and %.1f"
                + " primitives tested a ray), the framework's %.2f µs (%.1f boxes, %.1f primitives), the plain loop %.0f µs."
                + " Yours takes %.2f× the framework's time (at most 3× to pass) and is %.0f× faster than the loop (at least 20×).",
                SQUARES, you * 1e6, buildSeconds * 1e3, (double) yours.boxesTested() / RAYS, (double) yours.primitivesTested() / RAYS,
                them * 1e6, (double) counter.boxes(SearchCounter.CAMERA) / (ROUNDS * RAYS),
                (double) counter.tests(SearchCounter.CAMERA) / (ROUNDS * RAYS), linear * 1e6, you / them, linear / you);
        assertTrue(report + " [checksum " + checksum[0] + "]", you <= 3 * them && linear >= 20 * you);
        System.out.println(report);
    }
}
