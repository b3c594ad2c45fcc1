package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Shows the normal as a color, (n + 1)/2 per channel: a debugging view that needs no lights. */
public class RGBNormals extends Shader {
    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        return hit.normal.plus(Vec3.ONE).times(0.5);
    }

    @Override
    public Vec3 explain(IntersectionRecord hit, Ray ray, ShadingSteps steps) {
        Vec3 color = shade(hit, ray, steps.context(), 0);
        steps.row("L", "(n + 1)/2 = " + steps.vec(color) + "   (lights are not used)");
        return color;
    }
}
