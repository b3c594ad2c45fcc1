package ray.shading;

import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** Known wrong: Phong's original highlight, (r·e)^p with r the light mirrored about n, in place of Blinn's (n·h)^p. */
public class Lambertian extends LambertianShader {

    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        setDiffuseColor(diffuseColor);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        Vec3 kd = diffuseColorAt(hit);
        Vec3 sum = Vec3.ZERO;
        for (Light light : context.lights()) {
            Vec3 toLight = light.getPosition().minus(hit.location);
            double distanceSquared = toLight.lengthSquared();
            if (distanceSquared == 0) {
                continue; // a light at the point itself: no direction to it
            }
            double cosine = hit.normal.dot(toLight.normalized());
            // A light behind the surface adds nothing, so it costs no shadow ray.
            if (cosine <= 0 || !context.unoccluded(hit, light.getPosition())) {
                continue;
            }
            sum = sum.plus(kd.times(light.getIntensity()).times(cosine / distanceSquared));
        }
        return sum;
    }
}
