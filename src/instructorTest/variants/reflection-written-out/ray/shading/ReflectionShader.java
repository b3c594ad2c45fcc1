package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Correct: the lights in reverse order, v from the ray's origin, the shadow test after the share is worked out, Schlick with Math.pow and the reflection in a helper. */
public class ReflectionShader extends BrdfShader {

    public ReflectionShader() {
    }

    public ReflectionShader(String name, Brdf brdf, Vec3 diffuseColor, Texture texture, Vec3 mirrorCoefficient, Vec3 specularColor,
            Double exponent) {
        super(name, brdf, diffuseColor, texture, mirrorCoefficient, specularColor, exponent);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 v = ray.origin.minus(hit.location).normalized();
        Vec3 n = hit.normal;
        double nv = n.dot(v);
        if (nv <= 0) {
            return Vec3.ZERO;
        }
        Vec3 total = Vec3.ZERO;
        java.util.List<Light> lights = context.lights();
        for (int k = lights.size() - 1; k >= 0; k--) {
            Light light = lights.get(k);
            Vec3 toLight = light.getPosition().minus(hit.location);
            double r2 = toLight.lengthSquared();
            if (r2 == 0) {
                continue;
            }
            Vec3 l = toLight.normalized();
            double nl = n.dot(l);
            if (nl <= 0) {
                continue;
            }
            Vec3 f = brdf().value(diffuseColorAt(hit), n, l, v);
            Vec3 share = f.times(light.getIntensity()).times(nl / r2);
            if (context.unoccluded(hit, light.getPosition())) {
                total = total.plus(share);
            }
        }
        Vec3 km = getMirrorCoefficient();
        if (km.x == 0 && km.y == 0 && km.z == 0) {
            return total;
        }
        Vec3 mirrored = reflect(ray.direction.normalized(), n);
        double w = Math.pow(1 - nv, 5);
        Vec3 weight = new Vec3(km.x + (1 - km.x) * w, km.y + (1 - km.y) * w, km.z + (1 - km.z) * w);
        return total.plus(weight.times(context.radiance(hit, mirrored, depth + 1)));
    }

    /** d reflected about the unit normal n. */
    private static Vec3 reflect(Vec3 d, Vec3 n) {
        return d.minus(n.times(2 * d.dot(n)));
    }
}
