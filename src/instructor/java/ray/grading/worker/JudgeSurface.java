package ray.grading.worker;

import ray.IntersectionRecord;
import ray.Ray;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.ThrownData;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Bounds;
import ray.surface.Surface;

/**
 * A surface that lives on the judge's side and that a twin holds: a group's child (a test's fixed
 * surface, the solution's sphere, a mesh). The student's group calls it like any surface; the call
 * goes back to the judge, which runs the real surface and answers with what it changed. In a batch
 * ({@link BatchCalls}), a surface the judge certified as the framework's or the solution's answers
 * from the table the judge sent instead, and any other asks for its answer in the next round.
 */
final class JudgeSurface extends Surface {
    final int handle;
    private final Bounds bounds;
    /** Whether the judge vouches that this surface answers as the contract says (the solution's or the framework's). */
    final boolean certified;
    private final JudgeLink link;
    private final WorkerObjects objects;

    JudgeSurface(int handle, Bounds bounds, boolean certified, JudgeLink link, WorkerObjects objects) {
        this.handle = handle;
        this.bounds = bounds;
        this.certified = certified;
        this.link = link;
        this.objects = objects;
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        BatchCalls.Running batch = link.batch();
        if (batch != null) {
            return batch.judgeAnswer(this, out, ray);
        }
        WireOut request = new WireOut();
        request.u8(Protocol.CB_INTERSECT).i32(handle);
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
    public Bounds bounds() {
        return bounds;
    }

    @Override
    public String toString() {
        return "a surface of the test's (" + handle + ")";
    }

    /** What a judge-side surface threw, passed through the student's code to the judge as it was. */
    static final class JudgeSideThrew extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final transient ThrownData thrown;

        JudgeSideThrew(ThrownData thrown) {
            super(thrown.className + ": " + thrown.message, null, false, false);
            this.thrown = thrown;
        }
    }
}
