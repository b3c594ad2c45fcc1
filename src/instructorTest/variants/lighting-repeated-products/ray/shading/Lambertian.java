package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** A helper per light, which returns black for a light that cannot add anything. */
public class Lambertian extends LambertianShader {
    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        setDiffuseColor(diffuseColor);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 total = Vec3.ZERO;
        for (Light light : context.lights()) {
            total = total.plus(fromLight(light, hit, context));
        }
        return total;
    }

    private Vec3 fromLight(Light light, IntersectionRecord hit, ShadingContext context) {
        Vec3 toLight = light.getPosition().minus(hit.location);
        double lengthSquared = toLight.lengthSquared();
        double nDotL = lengthSquared > 0 ? hit.normal.dot(toLight) / Math.sqrt(lengthSquared) : 0;
        if (nDotL <= 0 || !context.unoccluded(hit, light.getPosition())) {
            return Vec3.ZERO;
        }
        Vec3 kd = diffuseColorAt(hit);
        Vec3 i = light.getIntensity();
        return new Vec3(kd.x * i.x, kd.y * i.y, kd.z * i.z).times(nDotL).times(1.0 / lengthSquared);
    }
}
