package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The exponent as repeated products (the exponents are whole numbers), and a helper per light. */
public class Phong extends PhongShader {
    public Phong() {
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 total = Vec3.ZERO;
        Vec3 toEye = ray.origin.minus(hit.location).normalized();
        for (Light light : context.lights()) {
            total = total.plus(fromLight(light, hit, toEye, context));
        }
        return total;
    }

    private Vec3 fromLight(Light light, IntersectionRecord hit, Vec3 toEye, ShadingContext context) {
        Vec3 toLight = light.getPosition().minus(hit.location);
        double lengthSquared = toLight.lengthSquared();
        if (lengthSquared == 0) {
            return Vec3.ZERO;
        }
        Vec3 l = toLight.normalized();
        Vec3 h = l.plus(toEye).normalized();
        double nDotL = Math.max(0, hit.normal.dot(l));
        double nDotH = Math.max(0, hit.normal.dot(h));
        double highlight = 1;
        for (int k = 0; k < (int) (double) getExponent(); k++) {
            highlight *= nDotH;
        }
        if (nDotL == 0 && highlight == 0 || !context.unoccluded(hit, light.getPosition())) {
            return Vec3.ZERO;
        }
        Vec3 reflected = diffuseColorAt(hit).times(nDotL).plus(getSpecularColor().times(highlight));
        return reflected.times(light.getIntensity()).times(1.0 / lengthSquared);
    }
}
