package ray.shading;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The lights by index from the last, the shadow test first, and the color summed channel by channel. */
public class Lambertian extends LambertianShader {
    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        setDiffuseColor(diffuseColor);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        List<Light> lights = context.lights();
        double r = 0;
        double g = 0;
        double b = 0;
        for (int i = lights.size() - 1; i >= 0; i--) {
            Light light = lights.get(i);
            if (light.getPosition().equals(hit.location) || !context.unoccluded(hit, light.getPosition())) {
                continue;
            }
            Vec3 toLight = light.getPosition().minus(hit.location);
            double r2 = toLight.dot(toLight);
            double cos = hit.normal.dot(toLight) / Math.sqrt(r2);
            if (cos > 0) {
                Vec3 kd = diffuseColorAt(hit);
                Vec3 intensity = light.getIntensity();
                r += kd.x * intensity.x * cos / r2;
                g += kd.y * intensity.y * cos / r2;
                b += kd.z * intensity.z * cos / r2;
            }
        }
        return new Vec3(r, g, b);
    }
}
