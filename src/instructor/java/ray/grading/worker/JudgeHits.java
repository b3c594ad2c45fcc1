package ray.grading.worker;

import ray.IntersectionRecord;
import ray.Ray;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Vec3;
import ray.render.HitShading;

/**
 * How a student's ray tracer has hits shaded on the worker's side: each hit goes back to the judge,
 * which shades it with the scene's shaders and lights ({@link Protocol#CB_SHADE_HIT}).
 */
final class JudgeHits implements HitShading {
    private final JudgeLink link;
    private final WorkerObjects objects;

    JudgeHits(JudgeLink link, WorkerObjects objects) {
        this.link = link;
        this.objects = objects;
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, int depth) {
        WireOut request = new WireOut();
        request.u8(Protocol.CB_SHADE_HIT);
        Records.write(request, hit, objects);
        Records.writeRay(request, ray);
        request.i32(depth);
        WireIn answer = link.ask(request);
        Vec3 color = answer.vec();
        answer.end();
        return color;
    }
}
