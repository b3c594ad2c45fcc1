package ray.shading;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * The course's 2019 shader: a BRDF lit by point lights, plus a mirror term weighted by Schlick's
 * approximation. Its BRDF, diffuse color or texture and mirror coefficient are kept by BrdfShader.
 */
public class ReflectionShader extends BrdfShader {

    public ReflectionShader() {
    }

    public ReflectionShader(String name, Brdf brdf, Vec3 diffuseColor, Texture texture, Vec3 mirrorCoefficient, Vec3 specularColor,
            Double exponent) {
        super(name, brdf, diffuseColor, texture, mirrorCoefficient, specularColor, exponent);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        // TODO(Task 10): return the light this surface sends back along the ray: its lights through its BRDF, and its mirror term.
        //   Return the light that leaves the hit toward the ray's origin: for each light that reaches the
        //   hit, the BRDF's value for that light's direction and the eye's times the light's intensity,
        //   times how squarely the light falls on the surface, falling off with the square of the
        //   distance; plus, for a surface with a mirror coefficient, the light arriving along the mirror
        //   direction, weighted by Schlick's approximation of how much a mirror reflects at that angle.
        //   Conventions (the reference images depend on them):
        //   - v is the unit vector from the hit toward the ray's origin and n is hit.normal (unit length).
        //     A hit seen from behind its normal (n·v ≤ 0) is black: no lights, no mirror term.
        //   - The lights are context.lights(); a light counts only if context.unoccluded(hit, its position)
        //     says nothing blocks the way to it; a light behind the surface, or exactly at the point, adds nothing.
        //   - The BRDF is brdf(): brdf().value(diffuseColorAt(hit), n, l, v), per channel; it has no cosine in it.
        //   - The mirror coefficient k_m is getMirrorCoefficient(), per channel; when it is zero in every
        //     channel there is no mirror term and no mirror ray. Otherwise the mirror direction is the ray's
        //     direction reflected about n, context.radiance(hit, that direction, depth + 1) is the light
        //     arriving along it (the renderer starts the ray off the surface; the ray's color stops paths at
        //     the course's limit), and Schlick's weight is k_m + (1 − k_m)(1 − n·v)^5, channel by channel.
        // HINTS steps
        //   1) Find the unit vector toward the eye and its cosine with the normal; if that cosine is not
        //      positive, return black.
        //   2) Look up the diffuse reflectance at the hit once.
        //   3) For each light: the vector to it, its length squared and the unit vector along it; skip the
        //      light when it is at the point, when its cosine with the normal is not positive or when it is
        //      blocked; otherwise add the BRDF's value times the light's intensity times that cosine,
        //      divided by the squared distance.
        //   4) If the mirror coefficient is not zero: reflect the ray's unit direction about the normal, ask
        //      the context for the light along it one depth deeper, and add it times Schlick's weight.
        // HINTS formulas
        //   1) d = ray.direction.normalized(), v = −d, n = hit.normal; if n·v ≤ 0, return Vec3.ZERO.
        //   2) ρd = diffuseColorAt(hit).
        //   3) For each light: toLight = light.getPosition() − hit.location, r² = toLight.lengthSquared(),
        //      l = toLight.normalized(); skip when r² = 0, n·l ≤ 0 or !context.unoccluded(hit, light.getPosition());
        //      L += brdf().value(ρd, n, l, v) ⊙ I · (n·l) / r², with I = light.getIntensity().
        //   4) If k_m ≠ (0, 0, 0): r = d − 2(d·n)n, R = k_m + (1 − k_m)(1 − n·v)^5 per channel,
        //      L += R ⊙ context.radiance(hit, r, depth + 1).
        // END HINTS
        // BEGIN SOLUTION
        Vec3 d = ray.direction.normalized();
        Vec3 v = d.negate();
        Vec3 n = hit.normal;
        double nv = n.dot(v);
        if (!(nv > 0)) {
            return Vec3.ZERO; // the back-face gate: lights and mirror alike
        }
        double r = 0;
        double g = 0;
        double b = 0;
        List<Light> lights = context.lights();
        if (!lights.isEmpty()) {
            Vec3 rhoD = diffuseColorAt(hit);
            for (Light light : lights) {
                Vec3 toLight = light.getPosition().minus(hit.location);
                double distanceSquared = toLight.lengthSquared();
                if (distanceSquared == 0) {
                    continue; // a light at the point itself: no direction to it
                }
                Vec3 l = toLight.normalized();
                double nl = n.dot(l);
                // A light below the surface adds nothing, so it costs no shadow ray.
                if (!(nl > 0) || !context.unoccluded(hit, light.getPosition())) {
                    continue;
                }
                Vec3 f = brdf().value(rhoD, n, l, v);
                Vec3 intensity = light.getIntensity();
                r += f.x * intensity.x * nl / distanceSquared;
                g += f.y * intensity.y * nl / distanceSquared;
                b += f.z * intensity.z * nl / distanceSquared;
            }
        }
        Vec3 km = getMirrorCoefficient();
        if (km.x != 0 || km.y != 0 || km.z != 0) {
            Vec3 mirrored = d.minus(n.times(2 * d.dot(n)));
            double m = 1 - Math.min(1, nv);
            double m5 = m * m * m * m * m;
            Vec3 arriving = context.radiance(hit, mirrored, depth + 1);
            r += (km.x + (1 - km.x) * m5) * arriving.x;
            g += (km.y + (1 - km.y) * m5) * arriving.y;
            b += (km.z + (1 - km.z) * m5) * arriving.z;
        }
        return new Vec3(r, g, b);
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
