package ray.bvh;

import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Hittable;
import ray.math.Vec3;

/**
 * What the framework keeps of a students' hierarchy ({@link BvhTree}): the primitives, their boxes,
 * the order the tree puts them in, and the counts of what its searches test. The framework fills it
 * ({@link StudentBvh}); {@link BvhTree} builds the nodes over it and searches them.
 */
public abstract class TreeData {
    /** A leaf holds at most this many primitives, unless all of them have the same center. */
    public static final int LEAF_SIZE = 4;

    /** The primitives, in the scene's order. */
    private Hittable[] primitives = new Hittable[0];
    /** Each primitive's box, by its place in the scene's order. */
    private Box[] boxes = new Box[0];
    /**
     * The primitives in the tree's order, by their place in the scene's order: a leaf holds
     * primitives order[start] to order[end − 1]. It starts as 0, 1, …, n − 1; building the tree
     * rearranges it.
     */
    protected int[] order = new int[0];
    private long boxesTested;
    private long primitivesTested;

    /** Over these primitives and their boxes (the same length), in the scene's order; the order starts as it. */
    final void prepare(Hittable[] primitives, Box[] boxes) {
        if (primitives.length != boxes.length) {
            throw new IllegalArgumentException(primitives.length + " primitives but " + boxes.length + " boxes");
        }
        this.primitives = primitives;
        this.boxes = boxes;
        this.order = new int[primitives.length];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
    }

    /** Shares a built tree's primitives, boxes and order (a renderer thread's copy, with counts of its own). */
    final void share(TreeData built) {
        this.primitives = built.primitives;
        this.boxes = built.boxes;
        this.order = built.order;
    }

    /** How many primitives the tree holds. */
    public int size() {
        return order.length;
    }

    /** The box of the primitive at place k of the tree's order (primitive order[k]). */
    protected Box boxAt(int k) {
        return boxes[order[k]];
    }

    /** The center of that box: what a split sorts by. */
    protected Vec3 centerAt(int k) {
        return boxes[order[k]].center();
    }

    /** The smallest box holding the boxes of the primitives at places start to end − 1 of the tree's order. */
    protected Box boxOf(int start, int end) {
        Box box = boxAt(start);
        for (int k = start + 1; k < end; k++) {
            box = box.union(boxAt(k));
        }
        return box;
    }

    /** The test of a ray against a node's box ({@link BoundingBoxes#hit}), counted. */
    protected boolean hitsBox(BvhNode node, Ray ray) {
        boxesTested++;
        return boxTests().hit(node.box, ray);
    }

    /** The intersection of the ray with the primitive at place k of the tree's order, counted: fills out only on a hit. */
    protected boolean hitsPrimitive(int k, IntersectionRecord out, Ray ray) {
        primitivesTested++;
        return primitives[order[k]].intersect(out, ray);
    }

    /** Whether the primitive at place k of the tree's order is hit anywhere in (ray.start, ray.end), counted. */
    protected boolean blocks(int k, Ray ray) {
        primitivesTested++;
        return primitives[order[k]].intersectsAny(ray);
    }

    /** Box tests so far. */
    public long boxesTested() {
        return boxesTested;
    }

    /** Primitive tests so far. */
    public long primitivesTested() {
        return primitivesTested;
    }

    /** Starts both counts again. */
    public void resetCounts() {
        boxesTested = 0;
        primitivesTested = 0;
    }

    private BoundingBoxes boxTests;

    private BoundingBoxes boxTests() {
        if (boxTests == null) {
            boxTests = new BoundingBoxes();
        }
        return boxTests;
    }

    /** Checks nothing: the framework checks the tree its build returns ({@link TreeInvariants}). */
    public void complete() {
    }
}
