package ray.bvh;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * The searches (BvhTree.closestHit and anyHit) against the plain loop over every primitive, on
 * seeded random scenes and thousands of rays; what a miss leaves; the ray's segment; the work a
 * search saves (the nearer child first, boxes beyond the closest hit skipped, a shadow search that
 * stops at its first hit). Most use a tree built here by halving the list, so they judge your
 * searches even before your build works; one searches your own tree.
 */
@Points(1)
public class BvhSearchTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass()).withTimeoutSeconds(SEARCH_SECONDS);

    /**
     * Graded, each primitive a search tests is asked of the grader's other process, so a search of
     * a few thousand rays takes seconds where it takes milliseconds here.
     */
    private static final int SEARCH_SECONDS = 120;

    private static void agree(Squares.Square[] squares, BvhTree tree, BvhNode root, Random random, Vec3 offset, double extent, int rays,
            String what) {
        for (int i = 0; i < rays; i++) {
            Ray ray = Squares.randomRay(random, offset, extent);
            if (random.nextInt(4) == 0) {
                ray.end = extent * random.nextDouble();
            }
            IntersectionRecord expected = Squares.linear(squares, ray);
            IntersectionRecord out = new IntersectionRecord();
            boolean hit = tree.closestHit(root, out, ray.copy());
            String call = "Over " + what + ", closestHit(root, out, ray from " + ray.origin + " along " + ray.direction + ", t in ("
                    + ray.start + ", " + ray.end + "))";
            if (expected == null) {
                assertFalse(call + " returned true (t " + out.t + "); the plain loop finds no hit", hit);
                continue;
            }
            assertTrue(call + " returned false; the plain loop hits square #" + (int) expected.texU + " at t " + expected.t
                    + Hints.fix(" (a box skipped that holds it: check hit, and which children you search)"), hit);
            assertEquals(call + " found square #" + (int) out.texU + " at t " + out.t + "; the closest is square #" + (int) expected.texU
                    + " at t " + expected.t + Hints.fix(" (after a hit, search the rest with the ray ended there)"), expected.t, out.t, 0);
            boolean blocked = tree.anyHit(root, ray.copy());
            assertTrue("Over " + what + ", anyHit(root, the same ray) returned false; the plain loop hits square #" + (int) expected.texU
                    + " at t " + expected.t, blocked);
        }
    }

    @Test
    public void closestHitAgreesWithThePlainLoop() {
        Random random = new Random(11);
        for (int n : new int[] {1, 3, 10, 100, 1000}) {
            Squares.Square[] squares = Squares.random(random, n, Vec3.ZERO, 4, 0.8);
            BvhNode[] root = new BvhNode[1];
            BvhTree tree = Squares.treeByPlace(squares, root);
            agree(squares, tree, root[0], random, Vec3.ZERO, 5, 400, n + " random squares");
        }
    }

    @Test
    public void closestHitFarFromTheOrigin() {
        Random random = new Random(12);
        Vec3 offset = v(-3e6, 1e6, 5e5);
        Squares.Square[] squares = Squares.random(random, 300, offset, 4, 0.8);
        BvhNode[] root = new BvhNode[1];
        BvhTree tree = Squares.treeByPlace(squares, root);
        agree(squares, tree, root[0], random, offset, 5, 1000, "300 random squares around " + offset);
    }

    @Test
    public void yourOwnTreeAgreesWithThePlainLoop() {
        Random random = new Random(13);
        Squares.Square[] squares = Squares.random(random, 2000, Vec3.ZERO, 10, 0.5);
        BvhTree tree = new BvhTree();
        Box[] boxes = Squares.boxes(squares);
        tree.prepare(squares, boxes);
        BvhNode root = tree.build(0, squares.length);
        String problem = TreeInvariants.firstProblem(root, tree, boxes);
        if (problem != null) {
            fail("Your build over 2000 random squares: " + problem);
        }
        agree(squares, tree, root, random, Vec3.ZERO, 11, 1000, "2000 random squares, your own tree");
    }

    @Test
    public void aMissLeavesTheRecordAsItWas() {
        Random random = new Random(14);
        Squares.Square[] squares = Squares.random(random, 50, Vec3.ZERO, 2, 0.3);
        BvhNode[] root = new BvhNode[1];
        BvhTree tree = Squares.treeByPlace(squares, root);
        IntersectionRecord out = new IntersectionRecord();
        Squares.Square first = squares[0];
        Vec3 along = v(first.axis == 0 ? 1 : 0, first.axis == 1 ? 1 : 0, first.axis == 2 ? 1 : 0);
        assertTrue("closestHit returned false for a ray at square #0's center, head on",
                tree.closestHit(root[0], out, new Ray(first.center.minus(along.times(10)), along, 0, Double.POSITIVE_INFINITY)));
        out.t = 42;
        out.texU = -7;
        assertFalse("closestHit returned true for a ray that passes far from every square",
                tree.closestHit(root[0], out, new Ray(v(100, 100, 100), v(1, 0, 0), 0, Double.POSITIVE_INFINITY)));
        assertEquals("After a miss, out.t changed", 42, out.t, 0);
        assertEquals("After a miss, out changed", -7, out.texU, 0);
    }

    /** 64 squares across the x axis at x = 0 … 63, each facing it: a ray along x meets all of them. */
    private static Squares.Square[] wall() {
        Squares.Square[] row = new Squares.Square[64];
        for (int i = 0; i < row.length; i++) {
            row[i] = new Squares.Square(i, 0, v(i, 0, 0), 1);
        }
        return row;
    }

    @Test
    public void theNearerChildFirstAndBoxesBeyondTheHitSkipped() {
        for (boolean forward : new boolean[] {true, false}) {
            Squares.Square[] row = wall();
            BvhNode[] root = new BvhNode[1];
            BvhTree tree = Squares.treeByPlace(row, root);
            Ray ray = forward ? new Ray(v(-5, 0.1, 0.2), v(1, 0, 0), 0, Double.POSITIVE_INFINITY)
                    : new Ray(v(70, 0.1, 0.2), v(-1, 0, 0), 0, Double.POSITIVE_INFINITY);
            IntersectionRecord out = new IntersectionRecord();
            tree.resetCounts();
            assertTrue(tree.closestHit(root[0], out, ray));
            int first = forward ? 0 : 63;
            assertEquals("A ray along " + (forward ? "+x" : "−x") + " through 64 squares in a row: found square #" + (int) out.texU,
                    first, (int) out.texU);
            long tests = tree.primitivesTested();
            assertTrue("A ray along " + (forward ? "+x" : "−x") + " through 64 squares in a row (leaves of " + TreeData.LEAF_SIZE
                    + ", in order along x) tested " + tests + " of them; a search that takes the nearer child first and skips boxes"
                    + " entered beyond the closest hit tests only the first leaf's " + TreeData.LEAF_SIZE
                    + Hints.fix(" (search the child nearer the ray's origin first, and the other with the ray ended at the hit)"),
                    tests <= TreeData.LEAF_SIZE);
        }
    }

    @Test
    public void anyHitStopsAtTheFirstHit() {
        Squares.Square[] row = wall();
        BvhNode[] root = new BvhNode[1];
        BvhTree tree = Squares.treeByPlace(row, root);
        for (Squares.Square square : row) {
            square.recording = true;
        }
        assertTrue("anyHit of a ray through 64 squares returned false",
                tree.anyHit(root[0], new Ray(v(70, 0.1, 0.2), v(-1, 0, 0), 0, Double.POSITIVE_INFINITY)));
        int calls = 0;
        for (Squares.Square square : row) {
            calls += square.calls.size();
        }
        // Every square is on the ray, so every test is a hit: a search that stops at its first makes one.
        int hits = 0;
        for (Squares.Square square : row) {
            for (boolean hit : square.calls) {
                hits += hit ? 1 : 0;
            }
        }
        assertEquals("anyHit of a ray through 64 squares made " + calls + " primitive tests, " + hits + " of them hits; a shadow search"
                + " stops at its first hit" + Hints.fix(" (return true as soon as a primitive blocks the ray)"), 1, hits);
    }

    @Test
    public void anyHitSeesOnlyTheRaysSegment() {
        Squares.Square[] row = wall();
        BvhNode[] root = new BvhNode[1];
        BvhTree tree = Squares.treeByPlace(row, root);
        assertFalse("anyHit of a ray that ends at x = −0.5, before the first square at x = 0, returned true",
                tree.anyHit(root[0], new Ray(v(-5, 0.1, 0.2), v(1, 0, 0), 0, 4.5)));
        assertFalse("anyHit of a ray that starts past the last square returned true",
                tree.anyHit(root[0], new Ray(v(-5, 0.1, 0.2), v(1, 0, 0), 68.5, 100)));
        assertTrue("anyHit of a ray from x = 10.5 to x = 11.5 (square #11 between) returned false",
                tree.anyHit(root[0], new Ray(v(10.5, 0.1, 0.2), v(1, 0, 0), 0, 1)));
    }
}
