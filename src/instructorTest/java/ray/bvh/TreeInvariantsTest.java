package ray.bvh;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Hittable;
import ray.math.Bounds;
import ray.math.Vec3;

/**
 * The framework's checks of a students' tree, each rule broken once by a hand-made tree: the order
 * not a permutation, a primitive in no leaf or in two, a node reached twice, a box that does not
 * hold a child or a primitive, an oversized leaf (allowed only when the centers coincide), a null root.
 */
public class TreeInvariantsTest {
    /** Points on the x axis at 0, 1, 2, … (boxes of one point), never hit: the checks read only boxes. */
    private static final class Dot implements Hittable {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            return false;
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            return false;
        }

        @Override
        public Bounds bounds() {
            return Bounds.EVERYTHING;
        }
    }

    private static Box at(double x) {
        return new Box(new Vec3(x, 0, 0), new Vec3(x, 0, 0));
    }

    private static Box span(double from, double to) {
        return new Box(new Vec3(from, 0, 0), new Vec3(to, 0, 0));
    }

    private static final int N = 8;
    private final Box[] boxes = new Box[N];
    private final BvhTree tree = new BvhTree();

    public TreeInvariantsTest() {
        Hittable[] dots = new Hittable[N];
        for (int i = 0; i < N; i++) {
            dots[i] = new Dot();
            boxes[i] = at(i);
        }
        tree.prepare(dots, boxes);
    }

    private BvhNode good() {
        return BvhNode.inner(span(0, 7), BvhNode.leaf(span(0, 3), 0, 4), BvhNode.leaf(span(4, 7), 4, 8));
    }

    private void broken(BvhNode root, String expected) {
        String problem = TreeInvariants.firstProblem(root, tree, boxes);
        assertEquals(expected, problem);
    }

    @Test
    public void aSoundTreePasses() {
        assertNull(TreeInvariants.firstProblem(good(), tree, boxes));
    }

    @Test
    public void aNullRoot() {
        broken(null, "build(0, 8) returned null; expected the root of a tree over 8 primitives");
    }

    @Test
    public void anOrderThatIsNotAPermutation() {
        tree.order[3] = 2;
        broken(good(), "order[3] is 2, which is already at an earlier place; order must hold each primitive 0 to 7 once");
        tree.order[3] = 99;
        broken(good(), "order[3] is 99; order must hold each primitive 0 to 7 once");
    }

    @Test
    public void aPrimitiveInNoLeafOrInTwo() {
        broken(BvhNode.inner(span(0, 7), BvhNode.leaf(span(0, 3), 0, 4), BvhNode.leaf(span(4, 6), 4, 7)),
                "no leaf holds place 7 of order (primitive 7): every primitive must be in a leaf");
        broken(BvhNode.inner(span(0, 7), BvhNode.leaf(span(0, 3), 0, 4),
                BvhNode.inner(span(3, 7), BvhNode.leaf(span(3, 5), 3, 6), BvhNode.leaf(span(6, 7), 6, 8))),
                "the root's right child's left child holds place 3 of order, which another leaf holds too");
    }

    @Test
    public void aNodeReachedTwice() {
        BvhNode half = BvhNode.leaf(span(0, 3), 0, 4);
        broken(BvhNode.inner(span(0, 7), half, half),
                "the root's right child is a node already in the tree: each node has one place, so each primitive is in one leaf");
    }

    @Test
    public void aBoxThatDoesNotHoldWhatIsBelowIt() {
        broken(BvhNode.inner(span(0, 6), BvhNode.leaf(span(0, 3), 0, 4), BvhNode.leaf(span(4, 7), 4, 8)),
                "the root's box " + span(0, 6) + " does not hold its right child's box " + span(4, 7));
        broken(BvhNode.inner(span(0, 7), BvhNode.leaf(span(0, 2), 0, 4), BvhNode.leaf(span(4, 7), 4, 8)),
                "the root's left child's box " + span(0, 2) + " does not hold primitive 3's box " + at(3));
    }

    @Test
    public void anOversizedLeafUnlessTheCentersCoincide() {
        broken(BvhNode.leaf(span(0, 7), 0, 8), "the root holds 8 primitives; a leaf may hold at most 4 unless their centers are all the same");
        for (int i = 0; i < N; i++) {
            boxes[i] = span(-i, i);
        }
        assertNull(TreeInvariants.firstProblem(BvhNode.leaf(span(-7, 7), 0, 8), tree, boxes));
    }

    @Test
    public void nodesRefuseWhatCannotBeATree() {
        assertThrows(IllegalArgumentException.class, () -> BvhNode.leaf(span(0, 1), 3, 3));
        assertThrows(IllegalArgumentException.class, () -> BvhNode.inner(span(0, 1), null, BvhNode.leaf(span(0, 1), 0, 1)));
        assertThrows(IllegalArgumentException.class, () -> new Box(new Vec3(1, 0, 0), new Vec3(0, 0, 0)));
        assertThrows(IllegalArgumentException.class, () -> new Box(new Vec3(Double.NaN, 0, 0), new Vec3(0, 0, 0)));
    }

    @Test
    public void theRenderersBuildNamesTheBrokenRule() {
        Hittable[] dots = {new Dot(), new Dot()};
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> StudentBvh.build(dots, new Box[] {at(0), null}));
        assertEquals("primitive 1 has no box (null)", e.getMessage());
        StudentBvh built = StudentBvh.build(dots, new Box[] {at(0), at(1)});
        assertTrue(built.root().isLeaf());
    }
}
