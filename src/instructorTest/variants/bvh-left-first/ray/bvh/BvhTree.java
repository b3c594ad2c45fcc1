package ray.bvh;

import java.util.Arrays;
import java.util.Comparator;
import ray.IntersectionRecord;
import ray.Ray;

/** Known wrong: the left child always first, wherever the ray comes from: the same hits, but a ray from the right tests boxes and primitives behind its first hit. */
public class BvhTree extends TreeData {

    public BvhNode build(int start, int end) {
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
    }

    public boolean closestHit(BvhNode node, IntersectionRecord out, Ray ray) {
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
        boolean leftFirst = true;
        BvhNode first = leftFirst ? node.left : node.right;
        BvhNode second = leftFirst ? node.right : node.left;
        if (closestHit(first, out, closestSoFar)) {
            closestSoFar.end = out.t;
            hit = true;
        }
        return closestHit(second, out, closestSoFar) || hit;
    }

    public boolean anyHit(BvhNode node, Ray ray) {
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
    }

    /** Where a box's center is along the ray: (c − o)·d. */
    private static double along(Box box, Ray ray) {
        return box.center().minus(ray.origin).dot(ray.direction);
    }
}
