package ray.shading;

import java.util.EnumSet;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Shaders lit by point lights: L = Σ over unshadowed lights of I ⊙ f(n, l, e) / r², where l is
 * the unit vector to the light, r the distance to it and e the unit vector toward the eye.
 * Subclasses give f, the reflectance term.
 */
public abstract class DirectLighting extends Shader {

    /** The light-independent factor f(n, l, e) that multiplies I/r²; zero means the light cannot add anything. */
    protected abstract Vec3 reflectance(Vec3 normal, Vec3 toLight, Vec3 toEye);

    @Override
    public Set<Effect> effects() {
        return EnumSet.of(Effect.LIGHTING, Effect.SHADOWS);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, Tracer tracer, int depth) {
        Vec3 toEye = towardEye(ray);
        double r = 0, g = 0, b = 0;
        for (Light light : tracer.lights()) {
            Vec3 toLightVector = light.getPosition().minus(hit.location);
            double distanceSquared = toLightVector.lengthSquared();
            Vec3 f = reflectance(hit.normal, toLightVector.normalized(), toEye);
            // A light whose unshadowed contribution is zero costs no shadow ray.
            if (f.x == 0 && f.y == 0 && f.z == 0 || !tracer.unoccluded(hit, light.getPosition())) {
                continue;
            }
            Vec3 intensity = light.getIntensity();
            r += f.x * intensity.x / distanceSquared;
            g += f.y * intensity.y / distanceSquared;
            b += f.z * intensity.z / distanceSquared;
        }
        return new Vec3(r, g, b);
    }
}
