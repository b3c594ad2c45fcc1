package ray.shading;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A shiny surface lit by the scene's point lights (Blinn–Phong): each light it sees adds a diffuse term
 * and a highlight, (kd ⊙ I · max(0, n·l) + ks ⊙ I · max(0, n·h)^p) / r², with h = normalize(l + e).
 * Its colors kd (or texture) and ks and its exponent p are kept by PhongShader.
 */
public class Phong extends PhongShader {

    public Phong() {
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        // TODO(Task 7): return the light this shiny surface sends back along the ray from the hit.
        //   Return the light that leaves the hit toward the ray's origin: the sum, over the scene's lights
        //   that reach the hit, of a diffuse term (as a matte surface's) and a highlight that is brightest
        //   where the direction halfway between the light and the eye lines up with the normal, both
        //   times the light's intensity and falling off with the square of the distance.
        //   Conventions (the reference images depend on them):
        //   - The lights are context.lights(); a light counts only if context.unoccluded(hit, its position)
        //     says nothing blocks the way to it (that helper traces the shadow ray, offset off the surface).
        //   - The diffuse color at the hit is diffuseColorAt(hit) (a texture's color there, if the shader
        //     has one); the highlight's color is getSpecularColor() (never textured) and its exponent
        //     getExponent(); the colors multiply channel by channel.
        //   - The diffuse term counts only where the light is in front of the surface; the highlight is
        //     not cut off there, as in the course's reference renderer (a light just behind the surface
        //     can still add a highlight); neither term is ever negative.
        //   - The eye is back along the ray (ray.direction need not be unit length); hit.normal is unit length;
        //     a light exactly at the point has no direction and adds nothing.
        // HINTS steps
        //   1) Look up the diffuse color at the hit once, and find the unit vector from the hit toward the eye.
        //   2) For each light: find the vector from the hit to the light, its length squared, and the unit
        //      vector along it; the half vector is the unit vector along the sum of that and the eye vector.
        //   3) The diffuse factor is the cosine between the normal and the light vector, and the highlight
        //      factor the cosine between the normal and the half vector raised to the exponent, each taken
        //      as zero when negative. Skip the light when it is at the point itself, when both factors
        //      are zero, or when the shadow test says the light is blocked.
        //   4) Add (the diffuse color times the diffuse factor plus the specular color times the highlight
        //      factor) times the light's intensity, divided by the squared distance; return the sum.
        // HINTS formulas
        //   1) kd = diffuseColorAt(hit), e = ray.direction.normalized().negate().
        //   2) For each light: toLight = light.getPosition() − hit.location, r² = toLight.lengthSquared(),
        //      l = toLight.normalized(), h = l.plus(e).normalized().
        //   3) diffuse = max(0, n·l) and specular = max(0, n·h)^p, with n = hit.normal and
        //      p = getExponent() (Math.pow). Skip the light when r² = 0, when both are 0, or when
        //      !context.unoccluded(hit, light.getPosition()) (testing the factors first saves a shadow ray).
        //   4) L += (kd · diffuse + ks · specular) ⊙ I / r², with ks = getSpecularColor(),
        //      I = light.getIntensity() and ⊙ channel by channel (Vec3.times(Vec3)); L starts at Vec3.ZERO.
        // END HINTS
        // BEGIN SOLUTION
        List<Light> lights = context.lights();
        if (lights.isEmpty()) {
            return Vec3.ZERO; // no light to reflect: not even the texture is looked up
        }
        Vec3 kd = diffuseColorAt(hit);
        Vec3 ks = getSpecularColor();
        Vec3 toEye = ray.direction.normalized().negate();
        Vec3 sum = Vec3.ZERO;
        for (Light light : lights) {
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
            if (diffuse == 0 && specular == 0 || !context.unoccluded(hit, light.getPosition())) {
                continue;
            }
            Vec3 reflected = kd.times(diffuse).plus(ks.times(specular));
            sum = sum.plus(reflected.times(light.getIntensity()).times(1 / distanceSquared));
        }
        return sum;
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
