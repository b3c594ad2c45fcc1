package ray.bvh;

import java.util.ArrayDeque;
import java.util.Deque;
import ray.IntersectionRecord;
import ray.Ray;

/**
 * Correct: the surface area heuristic over 12 bins of the centers on each axis (a leaf when no split
 * is cheaper and it is small enough), and searches with a stack of their own instead of recursion,
 * the far child pushed first, each node's box tested with the ray as shortened so far.
 */
public class BvhTree extends TreeData {
    private static final int BINS = 12;

    public BvhNode build(int start, int end) {
        Box box = boxOf(start, end);
        int n = end - start;
        if (n <= 1) {
            return BvhNode.leaf(box, start, end);
        }
        double bestCost = Double.POSITIVE_INFINITY;
        int bestAxis = -1;
        double bestLimit = 0;
        for (int axis = 0; axis < 3; axis++) {
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (int k = start; k < end; k++) {
                double c = centerAt(k).get(axis);
                lo = Math.min(lo, c);
                hi = Math.max(hi, c);
            }
            if (!(hi > lo)) {
                continue;
            }
            int[] counts = new int[BINS];
            Box[] boxes = new Box[BINS];
            for (int k = start; k < end; k++) {
                int b = bin(centerAt(k).get(axis), lo, hi);
                counts[b]++;
                boxes[b] = boxes[b] == null ? boxAt(k) : boxes[b].union(boxAt(k));
            }
            for (int split = 1; split < BINS; split++) {
                Box left = null;
                Box right = null;
                int nl = 0;
                int nr = 0;
                for (int b = 0; b < BINS; b++) {
                    if (boxes[b] == null) {
                        continue;
                    }
                    if (b < split) {
                        left = left == null ? boxes[b] : left.union(boxes[b]);
                        nl += counts[b];
                    } else {
                        right = right == null ? boxes[b] : right.union(boxes[b]);
                        nr += counts[b];
                    }
                }
                if (nl == 0 || nr == 0) {
                    continue;
                }
                double cost = area(left) * nl + area(right) * nr;
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestLimit = lo + (hi - lo) * split / BINS;
                }
            }
        }
        // A leaf when the centers cannot be told apart, or when it is small and no split is cheaper (a box test costs 1/8).
        if (bestAxis < 0 || (n <= LEAF_SIZE && 0.125 + bestCost / area(box) >= n)) {
            return BvhNode.leaf(box, start, end);
        }
        int axis = bestAxis;
        double limit = bestLimit;
        int i = start;
        for (int k = start; k < end; k++) {
            if (centerAt(k).get(axis) < limit) {
                int t = order[i];
                order[i] = order[k];
                order[k] = t;
                i++;
            }
        }
        if (i == start || i == end) {
            i = (start + end) / 2;
        }
        return BvhNode.inner(box, build(start, i), build(i, end));
    }

    private static int bin(double c, double lo, double hi) {
        int b = (int) (BINS * (c - lo) / (hi - lo));
        return Math.max(0, Math.min(BINS - 1, b));
    }

    private static double area(Box b) {
        double x = b.size(0);
        double y = b.size(1);
        double z = b.size(2);
        return x * y + y * z + z * x;
    }

    public boolean closestHit(BvhNode node, IntersectionRecord out, Ray ray) {
        Ray shortened = ray.copy();
        boolean hit = false;
        Deque<BvhNode> stack = new ArrayDeque<>();
        stack.push(node);
        while (!stack.isEmpty()) {
            BvhNode n = stack.pop();
            if (!hitsBox(n, shortened)) {
                continue;
            }
            if (n.isLeaf()) {
                for (int k = n.start; k < n.end; k++) {
                    if (hitsPrimitive(k, out, shortened)) {
                        shortened.end = out.t;
                        hit = true;
                    }
                }
            } else {
                double l = n.left.box.center().minus(ray.origin).dot(ray.direction);
                double r = n.right.box.center().minus(ray.origin).dot(ray.direction);
                if (l <= r) {
                    stack.push(n.right);
                    stack.push(n.left);
                } else {
                    stack.push(n.left);
                    stack.push(n.right);
                }
            }
        }
        return hit;
    }

    public boolean anyHit(BvhNode node, Ray ray) {
        Deque<BvhNode> stack = new ArrayDeque<>();
        stack.push(node);
        while (!stack.isEmpty()) {
            BvhNode n = stack.pop();
            if (!hitsBox(n, ray)) {
                continue;
            }
            if (n.isLeaf()) {
                for (int k = n.start; k < n.end; k++) {
                    if (blocks(k, ray)) {
                        return true;
                    }
                }
            } else {
                stack.push(n.right);
                stack.push(n.left);
            }
        }
        return false;
    }
}
