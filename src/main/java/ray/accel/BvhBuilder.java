package ray.accel;

import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveTask;
import ray.math.Bounds;

/**
 * Builds a {@link Bvh} by the surface area heuristic on binned centroids (Wald 2007, "On fast
 * construction of SAH-based bounding volume hierarchies"; pbrt-v4's {@code BVHAggregate}): a node's
 * primitives are split where the expected cost of testing the two children, each weighed by the
 * chance that a ray through the parent enters it (the ratio of surface areas), is least, or kept as
 * a leaf when no split is cheaper. Large subtrees are built in parallel; the result does not depend
 * on how many threads build it.
 */
public final class BvhBuilder {
    /** Centroid bins per split, on the axis where the centroids spread most. */
    static final int BINS = 16;
    /** Leaves hold at most this many primitives unless they cannot be split. */
    static final int MAX_LEAF = 4;
    /**
     * Two triangles or fewer always make a leaf: splitting them would save at most one triangle test
     * per ray for a node (32 bytes) per triangle, which a million-triangle mesh cannot afford.
     */
    static final int MIN_SPLIT = 2;
    /** The cost of testing a node's box, relative to one intersection test (pbrt-v4 takes ½ too). */
    static final double BOX_COST = 0.5;
    /** Subtrees at least this large are built as tasks of their own. */
    private static final int PARALLEL_ABOVE = 16 * 1024;

    private final double[] lo;
    private final double[] hi;
    private final double[] centroid;
    private final int[] order;

    private BvhBuilder(int n) {
        lo = new double[3 * n];
        hi = new double[3 * n];
        centroid = new double[3 * n];
        order = new int[n];
    }

    /**
     * The hierarchy over {@code primitives} (kept, not copied), whose file order ties are broken by; with
     * {@code split} false, a single leaf (the primitives' box, then each of them in file order).
     */
    public static Bvh build(Hittable[] primitives, boolean split) {
        int n = primitives.length;
        BvhBuilder b = new BvhBuilder(n);
        for (int i = 0; i < n; i++) {
            b.setBox(i, primitives[i].bounds());
            b.order[i] = i;
        }
        Node root = split ? b.split(0, n, 0) : b.leaf(0, n);
        Flat flat = new Flat(root.count());
        flat.write(root);
        return new Bvh(primitives, b.order, flat.boxes, flat.links, root.depth());
    }

    /** A primitive's box; one with an unknown or non-finite extent is everywhere (never skipped), centred at 0. */
    private void setBox(int i, Bounds box) {
        boolean known = box.isFinite() && !box.isEmpty();
        double[] min = {box.minX, box.minY, box.minZ};
        double[] max = {box.maxX, box.maxY, box.maxZ};
        for (int axis = 0; axis < 3; axis++) {
            lo[3 * i + axis] = known ? min[axis] : Double.NEGATIVE_INFINITY;
            hi[3 * i + axis] = known ? max[axis] : Double.POSITIVE_INFINITY;
            centroid[3 * i + axis] = known ? 0.5 * (min[axis] + max[axis]) : 0;
        }
    }

    /** A node being built: a leaf over order[first .. first + count) or two children. */
    private static final class Node {
        final double[] box = new double[6];
        int first;
        int count;
        int axis = -1;
        Node left;
        Node right;

        int count() {
            return 1 + (left == null ? 0 : left.count() + right.count());
        }

        /** Inner nodes on the longest path down: the most far children a search keeps waiting. */
        int depth() {
            return left == null ? 0 : 1 + Math.max(left.depth(), right.depth());
        }
    }

    private final class Split extends RecursiveTask<Node> {
        private final int first;
        private final int end;
        private final int depth;

        Split(int first, int end, int depth) {
            this.first = first;
            this.end = end;
            this.depth = depth;
        }

        @Override
        protected Node compute() {
            return split(first, end, depth);
        }
    }

    private Node leaf(int first, int end) {
        Node node = new Node();
        fillBox(node, first, end, new double[3], new double[3]);
        node.first = first;
        node.count = end - first;
        return node;
    }

    /** The subtree over order[first .. end). */
    private Node split(int first, int end, int depth) {
        Node node = new Node();
        double[] cmin = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] cmax = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        fillBox(node, first, end, cmin, cmax);
        node.first = first;
        node.count = end - first;
        int axis = cmax[0] - cmin[0] >= cmax[1] - cmin[1] && cmax[0] - cmin[0] >= cmax[2] - cmin[2] ? 0
                : cmax[1] - cmin[1] >= cmax[2] - cmin[2] ? 1 : 2;
        double extent = cmax[axis] - cmin[axis];
        if (node.count <= MIN_SPLIT || !(extent > 0) || depth >= Bvh.MAX_DEPTH - 2) {
            return node; // nothing to split by: one primitive, or all centroids in one place
        }
        int mid = partition(first, end, axis, cmin[axis], extent, node);
        if (mid < 0) {
            return node;
        }
        node.axis = axis;
        if (node.count >= PARALLEL_ABOVE) {
            // The calling thread takes one half and the common pool the other (from any thread).
            Split left = new Split(first, mid, depth + 1);
            Split right = new Split(mid, end, depth + 1);
            ForkJoinTask.invokeAll(left, right);
            node.left = left.join();
            node.right = right.join();
        } else {
            node.left = split(first, mid, depth + 1);
            node.right = split(mid, end, depth + 1);
        }
        return node;
    }

    /** The node's box, and the box of its primitives' centroids into cmin, cmax (which start empty). */
    private void fillBox(Node node, int first, int end, double[] cmin, double[] cmax) {
        java.util.Arrays.fill(cmin, Double.POSITIVE_INFINITY);
        java.util.Arrays.fill(cmax, Double.NEGATIVE_INFINITY);
        for (int axis = 0; axis < 3; axis++) {
            node.box[axis] = Double.POSITIVE_INFINITY;
            node.box[axis + 3] = Double.NEGATIVE_INFINITY;
        }
        for (int k = first; k < end; k++) {
            int i = order[k];
            for (int axis = 0; axis < 3; axis++) {
                node.box[axis] = Math.min(node.box[axis], lo[3 * i + axis]);
                node.box[axis + 3] = Math.max(node.box[axis + 3], hi[3 * i + axis]);
                cmin[axis] = Math.min(cmin[axis], centroid[3 * i + axis]);
                cmax[axis] = Math.max(cmax[axis], centroid[3 * i + axis]);
            }
        }
    }

    private int bin(int i, int axis, double cmin, double extent) {
        int b = (int) (BINS * ((centroid[3 * i + axis] - cmin) / extent));
        return Math.min(BINS - 1, Math.max(0, b));
    }

    /**
     * Chooses the cheapest of the BINS − 1 splits between bins by the surface area heuristic and
     * partitions order[first .. end) there; returns the first index of the right part, or −1 when
     * a leaf is cheaper (and small enough).
     */
    private int partition(int first, int end, int axis, double cmin, double extent, Node node) {
        int[] counts = new int[BINS];
        double[][] binBox = new double[BINS][];
        for (int k = first; k < end; k++) {
            int i = order[k];
            int b = bin(i, axis, cmin, extent);
            counts[b]++;
            binBox[b] = grow(binBox[b], i);
        }
        // Sweep from the right for the area and count of every right part, then from the left.
        double[] rightArea = new double[BINS];
        int[] rightCount = new int[BINS];
        double[] box = null;
        int count = 0;
        for (int b = BINS - 1; b > 0; b--) {
            box = union(box, binBox[b]);
            count += counts[b];
            rightArea[b] = area(box);
            rightCount[b] = count;
        }
        double bestCost = Double.POSITIVE_INFINITY;
        int bestSplit = -1;
        box = null;
        count = 0;
        for (int b = 0; b < BINS - 1; b++) {
            box = union(box, binBox[b]);
            count += counts[b];
            if (count == 0 || rightCount[b + 1] == 0) {
                continue;
            }
            double cost = area(box) * count + rightArea[b + 1] * rightCount[b + 1];
            if (cost < bestCost) {
                bestCost = cost;
                bestSplit = b;
            }
        }
        int n = end - first;
        double parentArea = area(node.box);
        double splitCost = BOX_COST + (parentArea > 0 && Double.isFinite(parentArea) ? bestCost / parentArea : n);
        if (bestSplit < 0 || (n <= MAX_LEAF && splitCost >= n)) {
            return -1;
        }
        // Partition in place: bins up to bestSplit to the left.
        int i = first;
        int j = end - 1;
        while (i <= j) {
            if (bin(order[i], axis, cmin, extent) <= bestSplit) {
                i++;
            } else {
                int swap = order[i];
                order[i] = order[j];
                order[j--] = swap;
            }
        }
        return i;
    }

    private double[] grow(double[] box, int i) {
        if (box == null) {
            return new double[] {lo[3 * i], lo[3 * i + 1], lo[3 * i + 2], hi[3 * i], hi[3 * i + 1], hi[3 * i + 2]};
        }
        for (int axis = 0; axis < 3; axis++) {
            box[axis] = Math.min(box[axis], lo[3 * i + axis]);
            box[axis + 3] = Math.max(box[axis + 3], hi[3 * i + axis]);
        }
        return box;
    }

    private static double[] union(double[] a, double[] b) {
        if (a == null) {
            return b == null ? null : b.clone();
        }
        if (b != null) {
            for (int axis = 0; axis < 3; axis++) {
                a[axis] = Math.min(a[axis], b[axis]);
                a[axis + 3] = Math.max(a[axis + 3], b[axis + 3]);
            }
        }
        return a;
    }

    /** Half the surface area of a box (the heuristic only compares ratios). */
    private static double area(double[] box) {
        if (box == null) {
            return 0;
        }
        double dx = box[3] - box[0];
        double dy = box[4] - box[1];
        double dz = box[5] - box[2];
        return dx * dy + dy * dz + dz * dx;
    }

    /** The nodes in depth first order, a node's first child right after it. */
    private static final class Flat {
        final float[] boxes;
        final int[] links;
        private int next;

        Flat(int nodes) {
            boxes = new float[6 * nodes];
            links = new int[2 * nodes];
        }

        int write(Node node) {
            int k = next++;
            for (int axis = 0; axis < 3; axis++) {
                double min = node.box[axis];
                double max = node.box[axis + 3];
                double pad = Bounds.pad(min, max);
                boxes[6 * k + axis] = floatBelow(min - pad);
                boxes[6 * k + axis + 3] = floatAbove(max + pad);
            }
            if (node.left == null) {
                links[2 * k] = node.first;
                links[2 * k + 1] = -node.count;
            } else {
                write(node.left);
                links[2 * k] = write(node.right);
                links[2 * k + 1] = node.axis;
            }
            return k;
        }

        private static float floatBelow(double x) {
            float f = (float) x;
            return f > x ? Math.nextDown(f) : f;
        }

        private static float floatAbove(double x) {
            float f = (float) x;
            return f < x ? Math.nextUp(f) : f;
        }
    }
}
