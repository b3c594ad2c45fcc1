package ray.bvh;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Correct: split at the midpoint of the centers' box on its longest axis, partitioned in place (the median when one side would be empty); the nearer child by the distance to its box's center. */
public class BvhTree extends TreeData {

    public BvhNode build(int start, int end) {
        Box box = boxOf(start, end);
        if (end - start <= LEAF_SIZE) {
            return BvhNode.leaf(box, start, end);
        }
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int k = start; k < end; k++) {
            Vec3 c = centerAt(k);
            for (int a = 0; a < 3; a++) {
                lo[a] = Math.min(lo[a], c.get(a));
                hi[a] = Math.max(hi[a], c.get(a));
            }
        }
        int axis = 0;
        for (int a = 1; a < 3; a++) {
            if (hi[a] - lo[a] > hi[axis] - lo[axis]) {
                axis = a;
            }
        }
        if (hi[axis] == lo[axis]) {
            return BvhNode.leaf(box, start, end);
        }
        double middle = 0.5 * (lo[axis] + hi[axis]);
        int i = start;
        int j = end - 1;
        while (i <= j) {
            if (centerAt(i).get(axis) < middle) {
                i++;
            } else {
                int t = order[i];
                order[i] = order[j];
                order[j] = t;
                j--;
            }
        }
        int mid = i;
        if (mid == start || mid == end) {
            // Every center on one side of the midpoint: sort by insertion and take the median.
            for (int k = start + 1; k < end; k++) {
                int p = order[k];
                double key = centerAt(k).get(axis);
                int m = k - 1;
                while (m >= start && centerAt(m).get(axis) > key) {
                    order[m + 1] = order[m];
                    m--;
                }
                order[m + 1] = p;
            }
            mid = (start + end) / 2;
        }
        return BvhNode.inner(box, build(start, mid), build(mid, end));
    }

    public boolean closestHit(BvhNode node, IntersectionRecord out, Ray ray) {
        if (!hitsBox(node, ray)) {
            return false;
        }
        Ray r = ray.copy();
        boolean found = false;
        if (node.isLeaf()) {
            for (int k = node.start; k < node.end; k++) {
                if (hitsPrimitive(k, out, r)) {
                    found = true;
                    r.end = out.t;
                }
            }
            return found;
        }
        double dl = node.left.box.center().minus(ray.origin).lengthSquared();
        double dr = node.right.box.center().minus(ray.origin).lengthSquared();
        BvhNode near = dl <= dr ? node.left : node.right;
        BvhNode far = near == node.left ? node.right : node.left;
        if (closestHit(near, out, r)) {
            found = true;
            r.end = out.t;
        }
        if (closestHit(far, out, r)) {
            found = true;
        }
        return found;
    }

    public boolean anyHit(BvhNode node, Ray ray) {
        if (!hitsBox(node, ray)) {
            return false;
        }
        if (!node.isLeaf()) {
            return anyHit(node.left, ray) || anyHit(node.right, ray);
        }
        for (int k = node.start; k < node.end; k++) {
            if (blocks(k, ray)) {
                return true;
            }
        }
        return false;
    }
}
