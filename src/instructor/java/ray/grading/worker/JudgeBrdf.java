package ray.grading.worker;

import ray.grading.wire.Protocol;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Vec3;
import ray.shading.Brdf;

/**
 * A 2019 shader's BRDF on the worker's side during one shade call: each value is asked of the judge
 * ({@link Protocol#CB_BRDF}), which evaluates the shader's own BRDF there, so that the student's
 * light loop is judged with the solution's BRDF.
 */
final class JudgeBrdf implements Brdf {
    private final JudgeLink link;
    private final String formula;

    JudgeBrdf(JudgeLink link, String formula) {
        this.link = link;
        this.formula = formula;
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        WireOut request = new WireOut();
        request.u8(Protocol.CB_BRDF).vec(rhoD).vec(n).vec(l).vec(v);
        WireIn answer = link.ask(request);
        Vec3 value = answer.vec();
        answer.end();
        return value;
    }

    @Override
    public String formula() {
        return formula;
    }
}
