package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: every light counts, blocked or not (no shadow test). */
public class Phong extends PhongShader {

    public Phong() {
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 kd = diffuseColorAt(hit);
        Vec3 ks = getSpecularColor();
        Vec3 toEye = ray.direction.normalized().negate();
        Vec3 sum = Vec3.ZERO;
        for (Light light : context.lights()) {
            Vec3 toLight = light.getPosition().minus(hit.location);
            double distanceSquared = toLight.lengthSquared();
            if (distanceSquared == 0) {
                continue; // a light at the point itself: no direction to it
            }
            Vec3 l = toLight.normalized();
            Vec3 half = l.plus(toEye).normalized();
            double diffuse = Math.max(0, hit.normal.dot(l));
            double specular = Math.pow(Math.max(0, hit.normal.dot(half)), getExponent());
            // A light that adds nothing even unshadowed costs no shadow ray.
            if (diffuse == 0 && specular == 0) {
                continue;
            }
            Vec3 reflected = kd.times(diffuse).plus(ks.times(specular));
            sum = sum.plus(reflected.times(light.getIntensity()).times(1 / distanceSquared));
        }
        return sum;
    }
}
