package ray.bvh;

import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Hittable;
import ray.accel.SearchCounter;

/**
 * The students' hierarchy as the renderer uses it ({@code --accel student}): built once over a list
 * of primitives by {@link BvhTree#build}, checked by {@link TreeInvariants}, then searched by
 * {@link BvhTree#closestHit} and {@link BvhTree#anyHit} from one {@link Search} per renderer thread
 * (each with counts of its own, added to the thread's {@link SearchCounter}).
 */
public final class StudentBvh {
    private final BvhTree built;
    private final BvhNode root;

    private StudentBvh(BvhTree built, BvhNode root) {
        this.built = built;
        this.root = root;
    }

    /**
     * The students' tree over {@code primitives}, whose boxes are {@code boxes} (the same length, at
     * least one).
     *
     * @throws BrokenTree naming the first rule of {@link TreeInvariants} the tree breaks
     */
    public static StudentBvh build(Hittable[] primitives, Box[] boxes) {
        if (primitives.length == 0) {
            throw new IllegalArgumentException("a tree needs at least one primitive");
        }
        for (int i = 0; i < boxes.length; i++) {
            if (boxes[i] == null) {
                throw new BrokenTree("primitive " + i + " has no box (null)");
            }
        }
        BvhTree tree = new BvhTree();
        tree.prepare(primitives, boxes);
        BvhNode root = tree.build(0, primitives.length);
        String problem = TreeInvariants.firstProblem(root, tree, boxes);
        if (problem != null) {
            throw new BrokenTree("BvhTree.build over " + primitives.length + " primitives: " + problem, root == null);
        }
        return new StudentBvh(tree, root);
    }

    /**
     * The students' searches over a tree the framework made ({@code root}, over the primitives in the
     * order given): how a search is tried before the students' build works. Not checked: the caller
     * made it.
     */
    public static StudentBvh withRoot(Hittable[] primitives, Box[] boxes, BvhNode root) {
        BvhTree tree = new BvhTree();
        tree.prepare(primitives, boxes);
        return new StudentBvh(tree, root);
    }

    public BvhNode root() {
        return root;
    }

    /** A search of its own for one thread: the tree shared, the counts its own. */
    public Search search() {
        return new Search(this);
    }

    /** One thread's searches of a students' tree. */
    public static final class Search {
        private final BvhTree tree = new BvhTree();
        private final BvhNode root;

        private Search(StudentBvh bvh) {
            tree.share(bvh.built);
            root = bvh.root;
        }

        /** The closest hit, as {@link BvhTree#closestHit} from the root finds it, its tests added to {@code counter} (may be null). */
        public boolean closestHit(IntersectionRecord out, Ray ray, SearchCounter counter) {
            tree.resetCounts();
            boolean hit = tree.closestHit(root, out, ray);
            count(counter);
            return hit;
        }

        /** Whether anything is hit, as {@link BvhTree#anyHit} from the root finds it. */
        public boolean anyHit(Ray ray, SearchCounter counter) {
            tree.resetCounts();
            boolean hit = tree.anyHit(root, ray);
            count(counter);
            return hit;
        }

        private void count(SearchCounter counter) {
            if (counter != null) {
                counter.count(tree.primitivesTested(), tree.boxesTested());
            }
        }
    }
}
