package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Each light's share worked out first (clamped with Math.max), then kept only if its shadow test passes. */
public class Lambertian extends LambertianShader {
    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        setDiffuseColor(diffuseColor);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 color = new Vec3(0, 0, 0);
        for (Light light : context.lights()) {
            Vec3 toLight = light.getPosition().minus(hit.location);
            double distance = toLight.length();
            if (distance == 0) {
                continue;
            }
            Vec3 l = toLight.times(1 / distance);
            Vec3 share = diffuseColorAt(hit).times(light.getIntensity()).times(Math.max(0, hit.normal.dot(l)) / (distance * distance));
            if (context.unoccluded(hit, light.getPosition())) {
                color = color.plus(share);
            }
        }
        return color;
    }
}
