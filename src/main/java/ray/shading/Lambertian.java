package ray.shading;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A matte surface lit by the scene's point lights: each light it sees adds kd ⊙ I · max(0, n·l) / r².
 * Its diffuse color kd (or texture) is kept by LambertianShader.
 */
public class Lambertian extends LambertianShader {

    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        setDiffuseColor(diffuseColor);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        // TODO(Task 7): return the light this matte surface sends back along the ray from the hit.
        //   Return the light that leaves the hit toward the ray's origin: the sum, over the scene's lights
        //   that reach the hit, of the light's intensity times the surface's diffuse color times how
        //   squarely the light falls on the surface, falling off with the square of the distance.
        //   Conventions (the reference images depend on them):
        //   - The lights are context.lights(); a light counts only if context.unoccluded(hit, its position)
        //     says nothing blocks the way to it (that helper traces the shadow ray, offset off the surface).
        //   - The diffuse color at the hit is diffuseColorAt(hit) (a texture's color there, if the shader
        //     has one); the colors multiply channel by channel; a light behind the surface adds nothing.
        //   - hit.normal is unit length; hit.location is the point; the light's intensity is its
        //     getIntensity() at distance 1; a light exactly at the point has no direction and adds nothing.
        // HINTS steps
        //   1) Look up the diffuse color at the hit once.
        //   2) For each light: find the vector from the hit to the light, its length squared, and the unit
        //      vector along it.
        //   3) Skip the light when it is at the point itself, when the cosine between the normal and that
        //      unit vector is not positive, or when the shadow test says the light is blocked.
        //   4) Add the diffuse color times the light's intensity times the cosine, divided by the squared
        //      distance, and return the sum.
        // HINTS formulas
        //   1) kd = diffuseColorAt(hit).
        //   2) For each light: toLight = light.getPosition() − hit.location, r² = toLight.lengthSquared(),
        //      l = toLight.normalized().
        //   3) With n·l = hit.normal.dot(l): skip the light when r² = 0, when n·l ≤ 0, or when
        //      !context.unoccluded(hit, light.getPosition()) (testing the cosine first saves a shadow ray).
        //   4) L += kd ⊙ I · (n·l) / r², with I = light.getIntensity() and ⊙ channel by channel
        //      (Vec3.times(Vec3)); return L, which starts at Vec3.ZERO.
        // END HINTS
        // BEGIN SOLUTION
        List<Light> lights = context.lights();
        if (lights.isEmpty()) {
            return Vec3.ZERO; // no light to reflect: not even the texture is looked up
        }
        Vec3 kd = diffuseColorAt(hit);
        Vec3 sum = Vec3.ZERO;
        for (Light light : lights) {
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
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
