package ray.grading.worker;

import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Hittable;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Bounds;

/**
 * A primitive of a students' tree ({@code ray.bvh.TreeData}) as the worker's copy of the tree holds
 * it: the primitive itself stays on the judge's side (a test's square, the solution's triangle), and
 * each test the student's search makes of it is asked back ({@link Protocol#CB_PRIMITIVE}) by the
 * tree's twin and the primitive's place in the scene's order. Its box is never asked: the tree's
 * boxes travel as the tree's state.
 */
final class JudgePrimitive implements Hittable {
    private final int tree;
    private final int index;
    private final JudgeLink link;
    private final WorkerObjects objects;

    private JudgePrimitive(int tree, int index, JudgeLink link, WorkerObjects objects) {
        this.tree = tree;
        this.index = index;
        this.link = link;
        this.objects = objects;
    }

    /** The {@code count} primitives of the tree twin {@code tree}, in the scene's order. */
    static Hittable[] array(int tree, int count, JudgeLink link, WorkerObjects objects) {
        Hittable[] primitives = new Hittable[count];
        for (int i = 0; i < count; i++) {
            primitives[i] = new JudgePrimitive(tree, i, link, objects);
        }
        return primitives;
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        WireOut request = new WireOut();
        request.u8(Protocol.CB_PRIMITIVE).i32(tree).i32(index).bool(false);
        Records.writeRay(request, ray);
        Records.write(request, out, objects);
        WireIn answer = link.ask(request);
        boolean hit = answer.bool();
        Records.readChanges(answer, out, objects);
        Records.readRayChanges(answer, ray);
        answer.end();
        return hit;
    }

    @Override
    public boolean intersectsAny(Ray ray) {
        WireOut request = new WireOut();
        request.u8(Protocol.CB_PRIMITIVE).i32(tree).i32(index).bool(true);
        Records.writeRay(request, ray);
        WireIn answer = link.ask(request);
        boolean hit = answer.bool();
        answer.end();
        return hit;
    }

    @Override
    public Bounds bounds() {
        return Bounds.EVERYTHING;
    }

    @Override
    public String toString() {
        return "primitive " + index + " of the tree";
    }
}
