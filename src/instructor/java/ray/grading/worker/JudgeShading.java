package ray.grading.worker;

import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Vec3;
import ray.shading.Light;
import ray.shading.ShadingContext;

/**
 * The shading context a student's shade gets on the worker's side: the scene's lights as the judge
 * sent them, and the shadow tests and mirror rays asked back of the judge, which traces them with
 * the renderer's (or the test's) own context ({@link Protocol#CB_UNOCCLUDED}, {@link Protocol#CB_RADIANCE}).
 */
final class JudgeShading implements ShadingContext {
    private final List<Light> lights;
    /** The hit the call gave: when the student's code passes this one, the judge uses its own. */
    private final IntersectionRecord given;
    private final JudgeLink link;
    private final WorkerObjects objects;

    JudgeShading(List<Light> lights, IntersectionRecord given, JudgeLink link, WorkerObjects objects) {
        this.lights = Collections.unmodifiableList(lights);
        this.given = given;
        this.link = link;
        this.objects = objects;
    }

    @Override
    public List<Light> lights() {
        return lights;
    }

    @Override
    public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
        WireIn answer = ask(Protocol.CB_UNOCCLUDED, hit, lightPosition, 0);
        boolean unoccluded = answer.bool();
        answer.end();
        return unoccluded;
    }

    @Override
    public Vec3 radiance(IntersectionRecord hit, Vec3 direction, int depth) {
        WireIn answer = ask(Protocol.CB_RADIANCE, hit, direction, depth);
        Vec3 radiance = answer.vec();
        answer.end();
        return radiance;
    }

    /** Asks the judge and returns its answer past the status ({@link JudgeLink#ask}). */
    private WireIn ask(int kind, IntersectionRecord hit, Vec3 vector, int depth) {
        WireOut request = new WireOut();
        request.u8(kind).u8(hit == null ? Protocol.HIT_NULL : hit == given ? Protocol.HIT_GIVEN : Protocol.HIT_OTHER);
        if (hit != null) {
            Records.write(request, hit, objects);
        }
        request.vec(vector);
        if (kind == Protocol.CB_RADIANCE) {
            request.i32(depth);
        }
        return link.ask(request);
    }
}
