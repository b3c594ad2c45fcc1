package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Correct: channel by channel, the shadow test first, (1 − n·v)^5 as products, the mirror term only where some channel of k_m is not zero. */
public class ReflectionShader extends BrdfShader {

    public ReflectionShader() {
    }

    public ReflectionShader(String name, Brdf brdf, Vec3 diffuseColor, Texture texture, Vec3 mirrorCoefficient, Vec3 specularColor,
            Double exponent) {
        super(name, brdf, diffuseColor, texture, mirrorCoefficient, specularColor, exponent);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 d = ray.direction.normalized();
        double nv = -hit.normal.dot(d);
        if (!(nv > 0)) {
            return new Vec3(0, 0, 0);
        }
        double[] sum = new double[3];
        for (Light light : context.lights()) {
            if (!context.unoccluded(hit, light.getPosition())) {
                continue;
            }
            Vec3 toLight = light.getPosition().minus(hit.location);
            double distance = toLight.length();
            if (distance == 0) {
                continue;
            }
            Vec3 l = toLight.times(1 / distance);
            double cosine = Math.max(0, hit.normal.dot(l));
            Vec3 f = brdf().value(diffuseColorAt(hit), hit.normal, l, d.negate());
            for (int c = 0; c < 3; c++) {
                sum[c] += f.get(c) * light.getIntensity().get(c) * cosine / (distance * distance);
            }
        }
        Vec3 km = getMirrorCoefficient();
        if (km.x > 0 || km.y > 0 || km.z > 0) {
            Vec3 r = d.minus(hit.normal.times(2 * d.dot(hit.normal)));
            Vec3 seen = context.radiance(hit, r, depth + 1);
            double m = 1 - nv;
            double m5 = m * m * m * m * m;
            for (int c = 0; c < 3; c++) {
                sum[c] += (km.get(c) + (1 - km.get(c)) * m5) * seen.get(c);
            }
        }
        return new Vec3(sum[0], sum[1], sum[2]);
    }
}
