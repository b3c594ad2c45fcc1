package ray.bvh;

import java.util.Arrays;
import java.util.Comparator;
import ray.IntersectionRecord;
import ray.Ray;

/**
 * A bounding volume hierarchy over a list of primitives (a mesh's triangles): built once, then
 * searched by every ray that reaches the mesh. TreeData holds the primitives and their boxes; the
 * tree is a {@link BvhNode} at its root.
 */
public class BvhTree extends TreeData {

    public BvhNode build(int start, int end) {
        // TODO(Task 12): build the subtree over the primitives at places start to end − 1 of order.
        //   Return its root: a leaf when there are few enough primitives, else an inner node whose two
        //   children are the subtrees over two parts of the range. You may rearrange order[start .. end).
        //   How to split is your choice (the midpoint of the longest axis, the median, the surface area
        //   heuristic).
        //   Conventions (the framework checks the tree you return):
        //   - every primitive is in exactly one leaf (and order still holds each primitive once);
        //   - each node's box holds its children's boxes, or its own primitives' boxes;
        //   - a leaf holds at most LEAF_SIZE primitives, unless all of them have the same center.
        // HINTS steps
        //   1) The node's box is the box of all its primitives.
        //   2) With LEAF_SIZE primitives or fewer, return a leaf over the range.
        //   3) Find the axis along which the primitives' centers spread most. If they do not spread at all,
        //      return a leaf.
        //   4) Sort the range by the centers' coordinate on that axis, and split it at its middle.
        //   5) Build both halves the same way and return an inner node over them.
        // HINTS formulas
        //   1) box = boxOf(start, end).
        //   2) if end − start ≤ LEAF_SIZE: return BvhNode.leaf(box, start, end).
        //   3) The centers' box: the union over k of new Box(centerAt(k), centerAt(k)); axis =
        //      longestAxis() of it; if its size(axis) is 0, return a leaf.
        //   4) Sort order[start .. end) by centerAt(k).get(axis); mid = (start + end) / 2.
        //   5) return BvhNode.inner(box, build(start, mid), build(mid, end)).
        // END HINTS
        // BEGIN SOLUTION
        Box box = boxOf(start, end);
        if (end - start <= LEAF_SIZE) {
            return BvhNode.leaf(box, start, end);
        }
        Box centers = new Box(centerAt(start), centerAt(start));
        for (int k = start + 1; k < end; k++) {
            centers = centers.union(new Box(centerAt(k), centerAt(k)));
        }
        int axis = centers.longestAxis();
        if (centers.size(axis) == 0) {
            return BvhNode.leaf(box, start, end);
        }
        Integer[] places = new Integer[end - start];
        for (int k = start; k < end; k++) {
            places[k - start] = k;
        }
        Arrays.sort(places, Comparator.comparingDouble(k -> centerAt(k).get(axis)));
        int[] sorted = new int[end - start];
        for (int i = 0; i < sorted.length; i++) {
            sorted[i] = order[places[i]];
        }
        System.arraycopy(sorted, 0, order, start, sorted.length);
        int mid = (start + end) / 2;
        return BvhNode.inner(box, build(start, mid), build(mid, end));
        // END SOLUTION
        // STUB: return null;
    }

    public boolean closestHit(BvhNode node, IntersectionRecord out, Ray ray) {
        // TODO(Task 12): find the closest hit among the primitives under node.
        //   Return whether any primitive under node is hit for t in (ray.start, ray.end), with out holding
        //   the closest hit; on a miss leave out exactly as it was.
        //   Conventions:
        //   - It finds the same hit the plain loop over every primitive would (a tie in t may keep either),
        //     but tests far fewer.
        //   - Skip a node whose box the ray misses (hitsBox), or enters only beyond the closest hit so far;
        //   - Visit the child nearer the ray's origin first, so its hits shorten the ray before the other.
        // HINTS steps
        //   1) If the ray misses the node's box, return false.
        //   2) In a leaf, test its primitives in turn (hitsPrimitive) against a copy of the ray, making the
        //      copy end at each hit, as the group does.
        //   3) In an inner node, search the nearer child first, then the other with the ray ended at the
        //      first one's hit, if it had one.
        // HINTS formulas
        //   1) if (!hitsBox(node, ray)) return false.
        //   2) Leaf: for k in [node.start, node.end): if hitsPrimitive(k, out, copy), copy.end = out.t.
        //   3) Nearer child: the one whose box's center c has the smaller (c − o)·d. Search it with a
        //      copy of the ray; after a hit, copy.end = out.t; then search the other with the copy.
        // END HINTS
        // BEGIN SOLUTION
        if (!hitsBox(node, ray)) {
            return false;
        }
        Ray closestSoFar = ray.copy();
        boolean hit = false;
        if (node.isLeaf()) {
            for (int k = node.start; k < node.end; k++) {
                if (hitsPrimitive(k, out, closestSoFar)) {
                    closestSoFar.end = out.t;
                    hit = true;
                }
            }
            return hit;
        }
        boolean leftFirst = along(node.left.box, ray) <= along(node.right.box, ray);
        BvhNode first = leftFirst ? node.left : node.right;
        BvhNode second = leftFirst ? node.right : node.left;
        if (closestHit(first, out, closestSoFar)) {
            closestSoFar.end = out.t;
            hit = true;
        }
        return closestHit(second, out, closestSoFar) || hit;
        // END SOLUTION
        // STUB: return false;
    }

    public boolean anyHit(BvhNode node, Ray ray) {
        // TODO(Task 12): return whether any primitive under node is hit for t in (ray.start, ray.end).
        //   A shadow ray asks only whether something is in the way.
        //   Conventions:
        //   - Stop at the first primitive that is in the way: no closest hit, and no test after the first
        //     hit.
        // HINTS steps
        //   1) If the ray misses the node's box, return false.
        //   2) In a leaf, return true at the first primitive that blocks the ray (blocks).
        //   3) In an inner node, return true if either child has a hit, searching the second only when
        //      the first has none.
        // HINTS formulas
        //   1) if (!hitsBox(node, ray)) return false.
        //   2) Leaf: for k in [node.start, node.end): if blocks(k, ray), return true; then return false.
        //   3) return anyHit(node.left, ray) || anyHit(node.right, ray).
        // END HINTS
        // BEGIN SOLUTION
        if (!hitsBox(node, ray)) {
            return false;
        }
        if (node.isLeaf()) {
            for (int k = node.start; k < node.end; k++) {
                if (blocks(k, ray)) {
                    return true;
                }
            }
            return false;
        }
        return anyHit(node.left, ray) || anyHit(node.right, ray);
        // END SOLUTION
        // STUB: return false;
    }
    // BEGIN SOLUTION

    /** Where a box's center is along the ray: (c − o)·d. */
    private static double along(Box box, Ray ray) {
        return box.center().minus(ray.origin).dot(ray.direction);
    }
    // END SOLUTION
}
