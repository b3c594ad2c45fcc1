package ray.grading.wire;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import java.lang.reflect.Field;
import org.junit.Test;
import ray.bvh.Box;
import ray.bvh.BvhNode;
import ray.math.Vec3;

/**
 * A students' tree on the wire: a tree and a shared subtree cross as they are; a cycle (which only
 * reflection can make) is refused where it is written, in the worker, as the student's code's own
 * failure; a table whose row names a later row, or a box or leaf that cannot be, is a wire error on
 * the judge's side.
 */
public class TreesWireTest {
    private static Box box(double a, double b) {
        return new Box(new Vec3(a, 0, 0), new Vec3(b, 1, 1));
    }

    private static WireIn roundTrip(WireOut out) {
        return new WireIn(out.toByteArray());
    }

    @Test
    public void aTreeAndASharedSubtreeCrossAsTheyAre() {
        BvhNode shared = BvhNode.leaf(box(0, 1), 0, 2);
        BvhNode root = BvhNode.inner(box(0, 3), BvhNode.inner(box(0, 3), shared, BvhNode.leaf(box(2, 3), 2, 4)), shared);
        WireOut out = new WireOut();
        Trees.writeTree(out, root);
        BvhNode back = Trees.readTree(roundTrip(out));
        assertEquals(box(0, 3), back.box);
        assertSame("a node the tree holds twice comes back as one node held twice", back.left.left, back.right);
        assertEquals(2, back.left.right.start);
        assertEquals(4, back.left.right.end);
        WireOut none = new WireOut();
        Trees.writeTree(none, null);
        assertNull(Trees.readTree(roundTrip(none)));
    }

    @Test
    public void aCycleIsRefusedWhereItIsWritten() throws Exception {
        BvhNode leaf = BvhNode.leaf(box(0, 1), 0, 1);
        BvhNode inner = BvhNode.inner(box(0, 1), leaf, BvhNode.leaf(box(0, 1), 1, 2));
        Field right = BvhNode.class.getDeclaredField("right");
        right.setAccessible(true);
        right.set(inner, inner);
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> Trees.writeTree(new WireOut(), inner));
        assertTrue(e.getMessage(), e.getMessage().contains("its own descendant"));
    }

    @Test
    public void aRowNamingALaterRowIsAWireError() {
        WireOut out = new WireOut();
        out.i32(2);
        Trees.writeBox(out, box(0, 1));
        out.bool(false).i32(1).i32(1);
        Trees.writeBox(out, box(0, 1));
        out.bool(true).i32(0).i32(1);
        assertThrows(WireError.class, () -> Trees.readTree(roundTrip(out)));
    }

    @Test
    public void aBoxOrALeafThatCannotBeIsAWireError() {
        WireOut inside = new WireOut();
        inside.i32(1).bool(true).vec(new Vec3(1, 0, 0)).vec(new Vec3(0, 0, 0)).bool(true).i32(0).i32(1);
        assertThrows(WireError.class, () -> Trees.readTree(roundTrip(inside)));
        WireOut empty = new WireOut();
        empty.i32(1);
        Trees.writeBox(empty, box(0, 1));
        empty.bool(true).i32(3).i32(3);
        assertThrows(WireError.class, () -> Trees.readTree(roundTrip(empty)));
    }
}
