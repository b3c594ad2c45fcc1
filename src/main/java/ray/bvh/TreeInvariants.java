package ray.bvh;

import java.util.ArrayDeque;
import java.util.Collections;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.Set;

/**
 * What every hierarchy must be, whichever way it was split, checked by the framework on the tree a
 * build returns: the order holds each primitive once; every primitive is in exactly one leaf (the
 * leaves' ranges cover the order once, and no node is reached twice); each node's box holds its
 * children's boxes, or its leaf's primitives' boxes; a leaf holds at most {@link TreeData#LEAF_SIZE}
 * primitives unless they all have the same center. A tree that breaks one would render wrongly or
 * slowly, and the first broken rule is reported in a sentence naming the node.
 */
public final class TreeInvariants {
    private TreeInvariants() {
    }

    /** What the tree rooted at {@code root} over {@code tree}'s primitives breaks first, or null when it is sound. */
    public static String firstProblem(BvhNode root, TreeData tree, Box[] boxes) {
        int n = tree.size();
        if (root == null) {
            return "build(0, " + n + ") returned null; expected the root of a tree over " + n + " primitives";
        }
        int[] order = tree.order;
        if (order == null || order.length != n) {
            return "order has " + (order == null ? "no array" : order.length + " places") + "; expected " + n;
        }
        boolean[] inOrder = new boolean[n];
        for (int k = 0; k < n; k++) {
            int p = order[k];
            if (p < 0 || p >= n || inOrder[p]) {
                return "order[" + k + "] is " + p + (p >= 0 && p < n ? ", which is already at an earlier place" : "")
                        + "; order must hold each primitive 0 to " + (n - 1) + " once";
            }
            inOrder[p] = true;
        }
        int[] covered = new int[n];
        Set<BvhNode> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        Deque<BvhNode> pending = new ArrayDeque<>();
        Deque<String> paths = new ArrayDeque<>();
        pending.push(root);
        paths.push("the root");
        while (!pending.isEmpty()) {
            BvhNode node = pending.pop();
            String path = paths.pop();
            if (!seen.add(node)) {
                return path + " is a node already in the tree: each node has one place, so each primitive is in one leaf";
            }
            if (node.isLeaf()) {
                if (node.start < 0 || node.end > n || node.start >= node.end) {
                    return path + " is a leaf over [" + node.start + ", " + node.end + "); expected a range within [0, " + n + ")";
                }
                for (int k = node.start; k < node.end; k++) {
                    if (covered[k]++ > 0) {
                        return path + " holds place " + k + " of order, which another leaf holds too";
                    }
                    Box box = boxes[order[k]];
                    if (!node.box.contains(box)) {
                        return path + "'s box " + node.box + " does not hold primitive " + order[k] + "'s box " + box;
                    }
                }
                if (node.size() > TreeData.LEAF_SIZE && !sameCenters(node, order, boxes)) {
                    return path + " holds " + node.size() + " primitives; a leaf may hold at most " + TreeData.LEAF_SIZE
                            + " unless their centers are all the same";
                }
            } else {
                if (!node.box.contains(node.left.box)) {
                    return path + "'s box " + node.box + " does not hold its left child's box " + node.left.box;
                }
                if (!node.box.contains(node.right.box)) {
                    return path + "'s box " + node.box + " does not hold its right child's box " + node.right.box;
                }
                pending.push(node.right);
                paths.push(path + "'s right child");
                pending.push(node.left);
                paths.push(path + "'s left child");
            }
        }
        for (int k = 0; k < n; k++) {
            if (covered[k] == 0) {
                return "no leaf holds place " + k + " of order (primitive " + order[k] + "): every primitive must be in a leaf";
            }
        }
        return null;
    }

    private static boolean sameCenters(BvhNode leaf, int[] order, Box[] boxes) {
        ray.math.Vec3 first = boxes[order[leaf.start]].center();
        for (int k = leaf.start + 1; k < leaf.end; k++) {
            if (!boxes[order[k]].center().equals(first)) {
                return false;
            }
        }
        return true;
    }
}
