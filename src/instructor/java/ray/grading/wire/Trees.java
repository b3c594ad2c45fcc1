package ray.grading.wire;

import java.lang.reflect.Field;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import ray.accel.Hittable;
import ray.bvh.Box;
import ray.bvh.BvhNode;
import ray.bvh.TreeData;
import ray.math.Vec3;

/**
 * The students' hierarchy on the wire: boxes, a tree of nodes as a table (children before their
 * parent, each child named by its row, so the table can name no cycle), and the fields of a
 * {@link TreeData} that the grader reads and sets where no public method does (the order a build
 * left, the counts a search made, a primitive by its place in the scene's order).
 */
public final class Trees {
    private static final Field ORDER = field("order");
    private static final Field PRIMITIVES = field("primitives");
    private static final Field BOXES_TESTED = field("boxesTested");
    private static final Field PRIMITIVES_TESTED = field("primitivesTested");

    private Trees() {
    }

    private static Field field(String name) {
        try {
            Field f = TreeData.class.getDeclaredField(name);
            f.setAccessible(true);
            return f;
        } catch (NoSuchFieldException e) {
            throw new IllegalStateException("TreeData has no field " + name + ": teach ray.grading.wire.Trees its new name", e);
        }
    }

    public static void writeBox(WireOut out, Box box) {
        out.bool(box != null);
        if (box != null) {
            out.vec(box.min).vec(box.max);
        }
    }

    /** A box or null; a box its constructor refuses (only a worker's tampering makes one) is a wire error. */
    public static Box readBox(WireIn in) {
        if (!in.bool()) {
            return null;
        }
        Vec3 min = in.vec();
        Vec3 max = in.vec();
        try {
            return new Box(min, max);
        } catch (IllegalArgumentException e) {
            throw new WireError("a box that cannot be: " + e.getMessage());
        }
    }

    /**
     * Writes the tree under {@code root} (null: no tree) as a table: its size, then each node once,
     * children before parents: box, whether a leaf, then its range or its children's rows.
     *
     * @throws IllegalStateException when a node is its own descendant (a cycle, made by reflection)
     */
    public static void writeTree(WireOut out, BvhNode root) {
        if (root == null) {
            out.i32(0);
            return;
        }
        Map<BvhNode, Integer> rows = new IdentityHashMap<>();
        Map<BvhNode, Boolean> open = new IdentityHashMap<>();
        List<BvhNode> table = new ArrayList<>();
        Deque<BvhNode> pending = new ArrayDeque<>();
        pending.push(root);
        while (!pending.isEmpty()) {
            BvhNode node = pending.peek();
            if (rows.containsKey(node)) {
                pending.pop();
                continue;
            }
            if (node.isLeaf() || (rows.containsKey(node.left) && rows.containsKey(node.right))) {
                pending.pop();
                open.remove(node);
                rows.put(node, table.size());
                table.add(node);
                continue;
            }
            if (open.put(node, Boolean.TRUE) != null) {
                throw new IllegalStateException("the tree has a node that is its own descendant: a tree cannot have a cycle");
            }
            if (!rows.containsKey(node.right)) {
                pending.push(node.right);
            }
            if (!rows.containsKey(node.left)) {
                pending.push(node.left);
            }
        }
        out.i32(table.size());
        for (BvhNode node : table) {
            writeNode(out, node, rows::get);
        }
    }

    /**
     * One node as a row, the same in a tree's table and in a definition of nodes: its box, whether a
     * leaf, then its range or its children as {@code child} names them (a row, a handle).
     */
    public static void writeNode(WireOut out, BvhNode node, java.util.function.ToIntFunction<BvhNode> child) {
        writeBox(out, node.box);
        out.bool(node.isLeaf());
        if (node.isLeaf()) {
            out.i32(node.start).i32(node.end);
        } else {
            out.i32(child.applyAsInt(node.left)).i32(child.applyAsInt(node.right));
        }
    }

    /**
     * Reads a row {@link #writeNode} wrote, its children found by {@code child} (which refuses a name it
     * was never given); a node that cannot be (no box, an empty range) is a wire error.
     */
    public static BvhNode readNode(WireIn in, java.util.function.IntFunction<BvhNode> child) {
        Box box = readBox(in);
        boolean leaf = in.bool();
        int a = in.i32();
        int b = in.i32();
        try {
            return leaf ? BvhNode.leaf(box, a, b) : BvhNode.inner(box, child.apply(a), child.apply(b));
        } catch (IllegalArgumentException e) {
            throw new WireError("a tree node that cannot be: " + e.getMessage());
        }
    }

    /** Reads a table {@link #writeTree} wrote: the root (its last row), or null for none. */
    public static BvhNode readTree(WireIn in) {
        int n = in.count(Protocol.MAX_ENTRIES, "tree nodes");
        BvhNode[] rows = new BvhNode[n];
        for (int k = 0; k < n; k++) {
            int row = k;
            rows[k] = readNode(in, r -> {
                if (r < 0 || r >= row) {
                    throw new WireError("a tree row " + row + " whose child is row " + r);
                }
                return rows[r];
            });
        }
        return n == 0 ? null : rows[n - 1];
    }

    public static int[] order(TreeData tree) {
        try {
            return (int[]) ORDER.get(tree);
        } catch (IllegalAccessException e) {
            throw new IllegalStateException(e);
        }
    }

    public static void setOrder(TreeData tree, int[] order) {
        try {
            ORDER.set(tree, order);
        } catch (IllegalAccessException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The primitive at place {@code index} of the scene's order. */
    public static Hittable primitive(TreeData tree, int index) {
        try {
            Hittable[] primitives = (Hittable[]) PRIMITIVES.get(tree);
            if (index < 0 || index >= primitives.length) {
                throw new WireError("a primitive " + index + " of " + primitives.length);
            }
            return primitives[index];
        } catch (IllegalAccessException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Adds to the tree's own counts: box tests as the worker's copy counted them, primitive tests as the judge served them. */
    public static void addCounts(TreeData tree, long boxes, long primitives) {
        try {
            BOXES_TESTED.setLong(tree, BOXES_TESTED.getLong(tree) + boxes);
            PRIMITIVES_TESTED.setLong(tree, PRIMITIVES_TESTED.getLong(tree) + primitives);
        } catch (IllegalAccessException e) {
            throw new IllegalStateException(e);
        }
    }
}
