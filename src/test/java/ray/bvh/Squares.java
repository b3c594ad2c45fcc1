package ray.bvh;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Hittable;
import ray.math.Bounds;
import ray.math.Vec3;

/**
 * The primitives the hierarchy's tests search: squares parallel to a pair of axes (in a plane x, y or
 * z = c), whose hits are simple enough to need no other task's code, and whose boxes are flat. A hit
 * records the square's number in {@code texU}, so a test can say which primitive was found.
 */
final class Squares {
    private Squares() {
    }

    /** A square in the plane {@code axis} = c, centered at {@code center}, reaching {@code half} along the other two axes. */
    static final class Square implements Hittable {
        final int id;
        final int axis;
        final Vec3 center;
        final double half;
        /** Every call of intersect and intersectsAny, and whether it hit, in order (for the any-hit tests). */
        final List<Boolean> calls = new ArrayList<>();
        boolean recording;

        Square(int id, int axis, Vec3 center, double half) {
            this.id = id;
            this.axis = axis;
            this.center = center;
            this.half = half;
        }

        /** The t where the ray meets the square, or NaN. */
        double hitT(Ray ray) {
            double d = ray.direction.get(axis);
            if (d == 0) {
                return Double.NaN;
            }
            double t = (center.get(axis) - ray.origin.get(axis)) / d;
            if (!(t > ray.start && t < ray.end)) {
                return Double.NaN;
            }
            Vec3 p = ray.pointAt(t);
            for (int other = 0; other < 3; other++) {
                if (other != axis && Math.abs(p.get(other) - center.get(other)) > half) {
                    return Double.NaN;
                }
            }
            return t;
        }

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            double t = hitT(ray);
            boolean hit = !Double.isNaN(t);
            if (recording) {
                calls.add(hit);
            }
            if (hit) {
                out.t = t;
                out.location = ray.pointAt(t);
                out.normal = axis == 0 ? new Vec3(1, 0, 0) : axis == 1 ? new Vec3(0, 1, 0) : new Vec3(0, 0, 1);
                out.texU = id;
            }
            return hit;
        }

        @Override
        public boolean intersectsAny(Ray ray) {
            boolean hit = !Double.isNaN(hitT(ray));
            if (recording) {
                calls.add(hit);
            }
            return hit;
        }

        Box box() {
            double[] min = {center.x - half, center.y - half, center.z - half};
            double[] max = {center.x + half, center.y + half, center.z + half};
            min[axis] = center.get(axis);
            max[axis] = center.get(axis);
            return new Box(new Vec3(min[0], min[1], min[2]), new Vec3(max[0], max[1], max[2]));
        }

        @Override
        public Bounds bounds() {
            Box box = box();
            return new Bounds(box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z);
        }

        @Override
        public String toString() {
            return "square #" + id + " in the plane " + "xyz".charAt(axis) + " = " + center.get(axis) + " around " + center + ", half size " + half;
        }
    }

    /** {@code n} squares of random axes, centers in the cube [−extent, extent]³ around {@code offset}, half sizes up to {@code maxHalf}. */
    static Square[] random(Random random, int n, Vec3 offset, double extent, double maxHalf) {
        Square[] squares = new Square[n];
        for (int i = 0; i < n; i++) {
            Vec3 c = new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                    extent * (2 * random.nextDouble() - 1)).plus(offset);
            squares[i] = new Square(i, random.nextInt(3), c, maxHalf * (0.1 + 0.9 * random.nextDouble()));
        }
        return squares;
    }

    static Box[] boxes(Square[] squares) {
        Box[] boxes = new Box[squares.length];
        for (int i = 0; i < squares.length; i++) {
            boxes[i] = squares[i].box();
        }
        return boxes;
    }

    /** The plain loop's closest hit (a tie keeps the earlier square), as the group finds it: the hit's t and square, or null. */
    static IntersectionRecord linear(Square[] squares, Ray ray) {
        IntersectionRecord best = null;
        Ray closestSoFar = ray.copy();
        for (Square square : squares) {
            IntersectionRecord record = new IntersectionRecord();
            if (square.intersect(record, closestSoFar)) {
                closestSoFar.end = record.t;
                best = record;
            }
        }
        return best;
    }

    /** A ray from a random point in the cube of {@code extent} around {@code offset} toward another. */
    static Ray randomRay(Random random, Vec3 offset, double extent) {
        Vec3 from = new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1)).plus(offset);
        Vec3 to = new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1)).plus(offset);
        return new Ray(from, to.minus(from).normalized(), 1e-9, Double.POSITIVE_INFINITY);
    }

    /** A tree over the squares without your build: order left as given, each range halved by place, boxes the unions. */
    static BvhTree treeByPlace(Square[] squares, BvhNode[] root) {
        BvhTree tree = new BvhTree();
        tree.prepare(squares, boxes(squares));
        root[0] = halve(tree, 0, squares.length);
        return tree;
    }

    private static BvhNode halve(BvhTree tree, int start, int end) {
        Box box = tree.boxOf(start, end);
        if (end - start <= TreeData.LEAF_SIZE) {
            return BvhNode.leaf(box, start, end);
        }
        int mid = (start + end) / 2;
        return BvhNode.inner(box, halve(tree, start, mid), halve(tree, mid, end));
    }
}
