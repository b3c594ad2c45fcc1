package ray.bvh;

/**
 * A node of a bounding volume hierarchy: its box, and either two children (an inner node) or a
 * range of primitives (a leaf): the primitives {@code order[start]} to {@code order[end − 1]} of
 * the tree that holds it ({@link BvhTree}). The box holds every primitive below the node.
 */
public final class BvhNode {
    public final Box box;
    /** The children of an inner node; both null in a leaf. */
    public final BvhNode left;
    public final BvhNode right;
    /** A leaf's primitives are order[start] to order[end − 1]; both 0 in an inner node. */
    public final int start;
    public final int end;

    private BvhNode(Box box, BvhNode left, BvhNode right, int start, int end) {
        if (box == null) {
            throw new IllegalArgumentException("a node needs a box");
        }
        this.box = box;
        this.left = left;
        this.right = right;
        this.start = start;
        this.end = end;
    }

    /** A leaf over the tree's order[start .. end). */
    public static BvhNode leaf(Box box, int start, int end) {
        if (start >= end) {
            throw new IllegalArgumentException("a leaf needs at least one primitive, got the range [" + start + ", " + end + ")");
        }
        return new BvhNode(box, null, null, start, end);
    }

    /** An inner node over two children. */
    public static BvhNode inner(Box box, BvhNode left, BvhNode right) {
        if (left == null || right == null) {
            throw new IllegalArgumentException("an inner node needs two children");
        }
        return new BvhNode(box, left, right, 0, 0);
    }

    public boolean isLeaf() {
        return left == null;
    }

    /** How many primitives a leaf holds (0 for an inner node). */
    public int size() {
        return end - start;
    }

    @Override
    public String toString() {
        return isLeaf() ? "leaf [" + start + ", " + end + ") in " + box : "node in " + box;
    }
}
