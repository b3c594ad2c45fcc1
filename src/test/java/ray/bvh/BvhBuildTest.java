package ray.bvh;

import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * The tree build (BvhTree.build), judged by the rules every hierarchy keeps whichever way it is
 * split ({@link TreeInvariants}): each primitive in exactly one leaf, each box holding what is below
 * it, small leaves; on sets of 1 to 5,000 seeded random primitives, primitives all at one center, and
 * two far clusters. Split by the midpoint, the median or the surface area heuristic: all pass.
 */
@Points(1)
public class BvhBuildTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /** Builds your tree over the squares and checks it; returns its root. */
    static BvhNode built(Squares.Square[] squares, String what) {
        BvhTree tree = new BvhTree();
        Box[] boxes = Squares.boxes(squares);
        tree.prepare(squares, boxes);
        BvhNode root = tree.build(0, squares.length);
        String problem = TreeInvariants.firstProblem(root, tree, boxes);
        assertNull("Over " + what + ": " + problem, problem);
        return root;
    }

    @Test
    public void onePrimitiveIsALeaf() {
        Squares.Square[] one = Squares.random(new Random(1), 1, Vec3.ZERO, 1, 0.5);
        BvhNode root = built(one, "one primitive");
        assertTrue("Over one primitive, build(0, 1) returned an inner node; expected a leaf", root.isLeaf());
    }

    @Test
    public void smallSetsKeepEveryRule() {
        Random random = new Random(2);
        for (int n = 2; n <= 40; n++) {
            built(Squares.random(random, n, Vec3.ZERO, 5, 0.5), n + " random primitives");
        }
    }

    @Test
    public void largeSetsKeepEveryRule() {
        Random random = new Random(3);
        for (int n : new int[] {100, 1000, 5000}) {
            built(Squares.random(random, n, v(100, -50, 20), 10, 0.3), n + " random primitives");
        }
    }

    @Test
    public void primitivesAtOneCenterCannotBeSplitAndNeedNotBe() {
        Squares.Square[] same = new Squares.Square[20];
        for (int i = 0; i < same.length; i++) {
            same[i] = new Squares.Square(i, i % 3, v(1, 2, 3), 0.5 + i % 2);
        }
        built(same, "20 squares all centered at (1, 2, 3) (no split separates their centers: a leaf may hold them all)");
    }

    @Test
    public void aLargerLeafIsRefusedWhenTheCentersDiffer() {
        Squares.Square[] row = new Squares.Square[12];
        for (int i = 0; i < row.length; i++) {
            row[i] = new Squares.Square(i, 0, v(i, 0, 0), 0.4);
        }
        BvhNode root = built(row, "12 squares in a row along x");
        assertTrue("Over 12 squares in a row, build(0, 12) returned a single leaf; expected it split (a leaf holds at most "
                + TreeData.LEAF_SIZE + ")", !root.isLeaf());
    }

    @Test
    public void twoFarClusters() {
        Random random = new Random(4);
        Squares.Square[] near = Squares.random(random, 50, v(0, 0, 0), 1, 0.1);
        Squares.Square[] far = Squares.random(random, 50, v(1e5, 1e5, -1e5), 1, 0.1);
        Squares.Square[] both = new Squares.Square[100];
        for (int i = 0; i < 50; i++) {
            both[2 * i] = new Squares.Square(2 * i, near[i].axis, near[i].center, near[i].half);
            both[2 * i + 1] = new Squares.Square(2 * i + 1, far[i].axis, far[i].center, far[i].half);
        }
        assertNotNull(built(both, "two clusters 170,000 apart, their primitives interleaved in the list"));
    }
}
