package ray.accel;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Bounds;

/**
 * A bounding volume hierarchy over a fixed list of primitives, in flat arrays: node k's box is
 * {@code boxes[6k .. 6k+5]} (min x, y, z, max x, y, z, as floats rounded outward and padded as
 * {@link Bounds} pads), and {@code links[2k], links[2k+1]} are either (first primitive,
 * −count) for a leaf or (second child, split axis) for an inner node, whose first child is k + 1.
 * Built by {@link BvhBuilder}.
 *
 * <p>Searches visit the child on the ray's near side first and shorten the ray at each hit, so
 * boxes beyond the closest hit so far are skipped. The leaves call each primitive's own
 * {@code intersect}: with triangles, the student's {@code Triangle.intersect} is still what hits.
 * The closest hit is the one a linear loop in file order finds, ties in t included (the earlier
 * primitive wins): see {@link #closestHit}.
 */
public final class Bvh {
    /** Deep enough for any tree the builder makes (it stops splitting at this depth). */
    static final int MAX_DEPTH = 64;

    /** The primitives in file order (the caller's array, shared, not copied). */
    final Hittable[] items;
    /** The primitives in tree order, by their index in {@link #items}: leaves are ranges of it, and the index breaks ties as a linear loop does. */
    final int[] order;
    final float[] boxes;
    final int[] links;
    /** The most far children a search can have waiting: the tree's depth. */
    private final int stackSize;

    Bvh(Hittable[] items, int[] order, float[] boxes, int[] links, int depth) {
        this.items = items;
        this.order = order;
        this.boxes = boxes;
        this.links = links;
        this.stackSize = Math.max(1, depth);
    }

    public int nodeCount() {
        return links.length / 2;
    }

    /**
     * Finds the closest hit of the ray for t in (ray.start, ray.end), into {@code out}, as the
     * linear loop over the primitives in file order does (each hit shortens the ray to end at it,
     * so the earlier of two hits at the same t wins). Out of order, a primitive earlier in the file
     * than the best so far is tested with the ray ending just past the best t (at the next double),
     * which admits a tie and nothing farther.
     */
    public boolean closestHit(IntersectionRecord out, Ray ray, SearchCounter counter) {
        Ray closestSoFar = ray.copy();
        double bestT = ray.end;
        int best = Integer.MAX_VALUE;
        double near = Bounds.widenedStart(ray.start);
        double far = Bounds.widenedEnd(bestT);
        double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
        double invX = 1 / ray.direction.x, invY = 1 / ray.direction.y, invZ = 1 / ray.direction.z;
        int[] stack = new int[stackSize];
        int top = 0;
        int node = 0;
        long tests = 0;
        long visited = 0;
        while (true) {
            visited++;
            if (mayHit(node, ox, oy, oz, invX, invY, invZ, near, far)) {
                int a = links[2 * node];
                int b = links[2 * node + 1];
                if (b >= 0) {
                    // Inner node: the near child now, the far one later.
                    if ((b == 0 ? invX : b == 1 ? invY : invZ) < 0) {
                        stack[top++] = node + 1;
                        node = a;
                    } else {
                        stack[top++] = a;
                        node = node + 1;
                    }
                    continue;
                }
                for (int i = a; i < a - b; i++) {
                    tests++;
                    int f = order[i];
                    closestSoFar.end = f < best && best != Integer.MAX_VALUE ? Math.nextUp(bestT) : bestT;
                    if (items[f].intersect(out, closestSoFar)) {
                        bestT = out.t;
                        best = f;
                        far = Bounds.widenedEnd(bestT);
                    }
                }
            }
            if (top == 0) {
                break;
            }
            node = stack[--top];
        }
        if (counter != null) {
            counter.count(tests, visited);
        }
        return best != Integer.MAX_VALUE;
    }

    /**
     * Whether any primitive is hit for t in (ray.start, ray.end); stops at the first hit found. The
     * same walk as {@link #closestHit} without its ordering and ties: kept as a loop of its own
     * because one method for both measured 7-10% slower renders (the JIT specialises each).
     */
    public boolean anyHit(Ray ray, SearchCounter counter) {
        IntersectionRecord scratch = new IntersectionRecord();
        double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
        double invX = 1 / ray.direction.x, invY = 1 / ray.direction.y, invZ = 1 / ray.direction.z;
        int[] stack = new int[stackSize];
        int top = 0;
        int node = 0;
        long tests = 0;
        long visited = 0;
        boolean hit = false;
        double near = Bounds.widenedStart(ray.start);
        double far = Bounds.widenedEnd(ray.end);
        search:
        while (true) {
            visited++;
            if (mayHit(node, ox, oy, oz, invX, invY, invZ, near, far)) {
                int a = links[2 * node];
                int b = links[2 * node + 1];
                if (b >= 0) {
                    stack[top++] = a;
                    node = node + 1;
                    continue;
                }
                for (int i = a; i < a - b; i++) {
                    tests++;
                    if (items[order[i]].intersect(scratch, ray)) {
                        hit = true;
                        break search;
                    }
                }
            }
            if (top == 0) {
                break;
            }
            node = stack[--top];
        }
        if (counter != null) {
            counter.count(tests, visited);
        }
        return hit;
    }

    /** Node k's box (padded when the tree was built) against the ray's widened interval [near, far]. */
    private boolean mayHit(int k, double ox, double oy, double oz, double invX, double invY, double invZ,
            double near, double far) {
        int o = 6 * k;
        return Bounds.slabsOverlap(boxes[o], boxes[o + 1], boxes[o + 2], boxes[o + 3], boxes[o + 4], boxes[o + 5],
                ox, oy, oz, invX, invY, invZ, near, far);
    }
}
