package ray.surface;

import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import ray.AnswerRounds;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.Bvh;
import ray.accel.BvhBuilder;
import ray.accel.SearchCounter;
import ray.bvh.BoundingBoxes;
import ray.bvh.Box;
import ray.bvh.BrokenTree;
import ray.bvh.StudentBvh;
import ray.math.Affine;
import ray.math.Bounds;
import ray.shading.Effect;

/**
 * A surface made of triangles that it builds itself ({@link Box}, {@link Mesh}), hit by the
 * closest of them: the framework's own search, so a box or mesh needs the student's
 * {@link Triangle} but not their {@link Group}. A set of {@link #LINEAR_BELOW} triangles or more
 * is searched through a bounding volume hierarchy ({@link Bvh}) built when the set is; a smaller one
 * by its box and then a loop over every triangle, which costs less than a tree would save. Either
 * way the hit is the one the plain loop in file order finds, ties in t keeping the earlier triangle
 * ({@link #closestHitLinear} is that loop, for rendering without acceleration).
 */
public abstract class TriangleSet extends Surface {
    /** Sets smaller than this keep a single leaf: their box, then every triangle. */
    public static final int LINEAR_BELOW = 8;

    /** In file order; an array, since a mesh may have millions (4 bytes each, no list's slack). */
    private Triangle[] triangles = new Triangle[0];
    private Bvh bvh;
    /** The students' tree over the triangles, built the first time a search asks for it. */
    private StudentBvh studentTree;

    /**
     * Replaces the triangles (by complete(), once the properties are known) and builds their
     * hierarchy. No triangles (a box flat on two axes) make no hierarchy, since a {@link Bvh} cannot
     * hold an empty leaf: the set is then never hit.
     */
    protected void setTriangles(List<Triangle> built) {
        triangles = built.toArray(new Triangle[0]);
        bvh = triangles.length == 0 ? null : BvhBuilder.build(triangles, hasTree());
        studentTree = null;
    }

    /**
     * The students' tree over the triangles ({@code --accel student}): each triangle's box from
     * {@link BoundingBoxes#ofTriangle}, the tree from {@link ray.bvh.BvhTree#build}, built once and
     * checked ({@link StudentBvh#build}).
     *
     * @throws BrokenTree when the students' code gives no box or a broken tree, saying which
     */
    public synchronized StudentBvh studentTree() {
        if (studentTree == null) {
            BoundingBoxes boxes = new BoundingBoxes();
            Box[] triangleBoxes = new Box[triangles.length];
            for (int i = 0; i < triangles.length; i++) {
                Triangle t = triangles[i];
                triangleBoxes[i] = boxes.ofTriangle(t.getV0(), t.getV1(), t.getV2());
                if (triangleBoxes[i] == null) {
                    throw new BrokenTree("BoundingBoxes.ofTriangle returned null for " + this + "'s " + partName(t, i)
                            + " (" + t.getV0() + ", " + t.getV1() + ", " + t.getV2() + "); expected its box");
                }
            }
            studentTree = StudentBvh.build(triangles, triangleBoxes);
        }
        return studentTree;
    }

    @Override
    public List<Surface> children() {
        return Collections.unmodifiableList(triangles());
    }

    /** Searched through its hierarchy, or by the plain loop without acceleration, counting both kinds of test. */
    @Override
    public Surface searchCopy(Acceleration acceleration, SearchCounter counter) {
        // While grading, a set of the student's triangles may be searched where the student's Triangle runs (AnswerRounds).
        return AnswerRounds.searched(this, acceleration.accelerated(), new CountedCopy.OfTriangles(this, acceleration, counter));
    }

    /** Drawn as one shape of triangles. */
    @Override
    public void sketch(Sketch sketch, Affine toWorld) {
        sketch.mesh(triangles(), toWorld.after(childPlacement()));
    }

    /** The triangles in file order. */
    public List<Triangle> triangles() {
        return Collections.unmodifiableList(Arrays.asList(triangles));
    }

    public int triangleCount() {
        return triangles.length;
    }

    /** Whether the set is searched through a tree (rather than its box and then every triangle). */
    public boolean hasTree() {
        return triangles.length >= LINEAR_BELOW;
    }

    /** The hierarchy's node count (1 for a set searched by its box alone, 0 before the triangles are built or without any). */
    public int treeNodes() {
        return bvh == null ? 0 : bvh.nodeCount();
    }

    /** A set big enough for its hierarchy calls for acceleration (and the plan says so). */
    @Override
    public Set<Effect> effects() {
        return hasTree() ? Set.of(Effect.ACCELERATION) : Set.of();
    }

    @Override
    public Bounds bounds() {
        Bounds box = Bounds.EMPTY;
        for (Triangle triangle : triangles) {
            box = box.union(triangle.bounds());
        }
        return box;
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        return closestHit(out, ray, null);
    }

    @Override
    public boolean intersectsAny(Ray ray) {
        return anyHit(ray, null);
    }

    /** The closest hit through the hierarchy, counting the tests and boxes into {@code counter} (may be null). */
    public boolean closestHit(IntersectionRecord out, Ray ray, SearchCounter counter) {
        return bvh != null && bvh.closestHit(out, ray, counter);
    }

    /** Whether any triangle is hit, through the hierarchy, stopping at the first. */
    public boolean anyHit(Ray ray, SearchCounter counter) {
        return bvh != null && bvh.anyHit(ray, counter);
    }

    /**
     * The closest hit by the plain loop over every triangle in file order, each hit shortening the
     * ray (what {@link Group} does, and what the hierarchy's answer is proven against).
     */
    public boolean closestHitLinear(IntersectionRecord out, Ray ray, SearchCounter counter) {
        Ray closestSoFar = ray.copy();
        boolean hitAny = false;
        for (Triangle triangle : triangles) {
            if (triangle.intersect(out, closestSoFar)) {
                closestSoFar.end = out.t;
                hitAny = true;
            }
        }
        if (counter != null) {
            counter.count(triangles.length, 0);
        }
        return hitAny;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[" + triangles.length + " triangles]";
    }

    /** A triangle of the set, by its number: "triangle #8". */
    @Override
    public String partName(Surface part, int index) {
        return "triangle #" + (index + 1);
    }
}
