package ray.shading;

import java.util.EnumSet;
import java.util.Set;
import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * The course's 2019 shader: a {@link Brdf} lit by point lights, plus an optional mirror term. For a
 * hit seen along a ray of unit direction d, with v = −d and n the shading normal:
 *
 * <ol>
 * <li>a hit seen from behind its normal (n·v ≤ 0) is black, lights and mirror alike;
 * <li>each light whose shadow ray is clear adds f(l, v) ⊙ I · max(0, n·l) / r²;
 * <li>when the mirror coefficient k_m is not zero, the ray reflected about n,
 * d_r = d − 2(d·n)n, brings back radiance weighted per channel by Schlick's
 * R = k_m + (1 − k_m)(1 − n·v)^5, unless the path already has {@link Course#MAX_PATH_HITS_2019}
 * hits (the course returns black for a ray past that depth, so no ray is traced).
 * </ol>
 *
 * The loader makes one from a Lambertian or Phong element when the scene loads under 2019's
 * conventions ({@link Shader#forCourse}); it is never written in a scene file itself.
 */
public final class ReflectionShader extends Shader {
    private final String name;
    private final Brdf brdf;
    private final Vec3 diffuseColor;
    private final Texture texture;
    private final Vec3 mirrorCoefficient;
    private final Vec3 specularColor;
    private final Double exponent;

    /**
     * @param name              the scene's name for it ("Lambertian", "Phong"), which trace shows
     * @param specularColor     ks and {@code exponent} p, for the description; null for a shader without a highlight
     */
    public ReflectionShader(String name, Brdf brdf, Vec3 diffuseColor, Texture texture, Vec3 mirrorCoefficient,
            Vec3 specularColor, Double exponent) {
        this.name = name;
        this.brdf = brdf;
        this.diffuseColor = diffuseColor;
        this.texture = texture;
        this.mirrorCoefficient = mirrorCoefficient;
        this.specularColor = specularColor;
        this.exponent = exponent;
    }

    public Brdf brdf() {
        return brdf;
    }

    public Vec3 getMirrorCoefficient() {
        return mirrorCoefficient;
    }

    @Override
    public Vec3 getDiffuseColor() {
        return diffuseColor;
    }

    @Override
    public Texture getTexture() {
        return texture;
    }

    @Override
    public Vec3 diffuseColorAt(IntersectionRecord hit) {
        return texture != null ? texture.colorAt(hit) : diffuseColor;
    }

    @Override
    public Vec3 getSpecularColor() {
        return specularColor;
    }

    @Override
    public Double getExponent() {
        return exponent;
    }

    @Override
    public Course course() {
        return Course.Y2019;
    }

    private boolean mirrors() {
        return mirrorCoefficient.x != 0 || mirrorCoefficient.y != 0 || mirrorCoefficient.z != 0;
    }

    @Override
    public Set<Effect> effects() {
        Set<Effect> effects = EnumSet.of(Effect.LIGHTING, Effect.SHADOWS);
        if (specularColor != null) {
            effects.add(Effect.SPECULAR);
        }
        if (texture != null) {
            effects.add(Effect.TEXTURES);
        }
        if (mirrors()) {
            effects.add(Effect.REFLECTION);
        }
        return effects;
    }

    /** Schlick's weight of the mirror term, per channel, for n·v = {@code cosine}: k_m + (1 − k_m)(1 − n·v)^5. */
    public Vec3 schlick(double cosine) {
        double m = 1 - Math.min(1, cosine);
        double m5 = m * m * m * m * m;
        return new Vec3(mirrorCoefficient.x + (1 - mirrorCoefficient.x) * m5,
                mirrorCoefficient.y + (1 - mirrorCoefficient.y) * m5,
                mirrorCoefficient.z + (1 - mirrorCoefficient.z) * m5);
    }

    /**
     * The back-face gate: whether the hit is seen from behind its shading normal (n·v ≤ 0, v toward
     * the ray's origin), where 2019's shader returns black without evaluating anything.
     */
    public static boolean seenFromBehind(IntersectionRecord hit, Ray ray) {
        return !(hit.normal.dot(towardEye(ray)) > 0);
    }

    @Override
    public boolean evaluatesAt(IntersectionRecord hit, Ray ray) {
        return !seenFromBehind(hit, ray);
    }

    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        if (seenFromBehind(hit, ray)) {
            return Vec3.ZERO; // the back-face gate: lights and mirror alike
        }
        Vec3 d = ray.direction.normalized();
        Vec3 v = d.negate();
        Vec3 n = hit.normal;
        double nv = n.dot(v);
        double r = 0, g = 0, b = 0;
        if (!context.lights().isEmpty()) {
            Vec3 rhoD = diffuseColorAt(hit);
            for (Light light : context.lights()) {
                Vec3 toLight = light.getPosition().minus(hit.location);
                double r2 = toLight.lengthSquared();
                Vec3 l = toLight.normalized();
                double nl = n.dot(l);
                // f is evaluated for every light (as the render counters count it), but a light below
                // the surface, or one f gives nothing, adds nothing and costs no shadow ray.
                Vec3 f = brdf.value(rhoD, n, l, v);
                if (!(nl > 0) || f.x == 0 && f.y == 0 && f.z == 0 || !context.unoccluded(hit, light.getPosition())) {
                    continue;
                }
                Vec3 intensity = light.getIntensity();
                r += f.x * intensity.x * nl / r2;
                g += f.y * intensity.y * nl / r2;
                b += f.z * intensity.z * nl / r2;
            }
        }
        // Ray depth counts from 0 at the camera, so this hit is the (depth + 1)-th of its path.
        if (mirrors() && depth + 2 <= Course.MAX_PATH_HITS_2019) {
            Vec3 mirrored = d.minus(n.times(2 * d.dot(n)));
            Vec3 weight = schlick(nv);
            Vec3 arriving = context.radiance(hit, mirrored, depth + 1);
            r += weight.x * arriving.x;
            g += weight.y * arriving.y;
            b += weight.z * arriving.z;
        }
        return new Vec3(r, g, b);
    }

    @Override
    public String describe(DoubleFunction<String> number) {
        String s = super.describe(number) + " (2019: f = " + brdf.formula() + ")";
        return mirrors() ? s + ", mirror k_m = " + mirrorCoefficient.format(number) : s;
    }

    @Override
    public Vec3 explain(IntersectionRecord hit, Ray ray, ShadingSteps steps) {
        Vec3 v = towardEye(ray);
        double nv = hit.normal.dot(v);
        steps.line("L = Σ over lights of f ⊙ I · max(0, n·l) / r², f = " + brdf.formula()
                + (mirrors() ? ", + R ⊙ L_mirror, R = k_m + (1 − k_m)(1 − n·v)^5 (Schlick)" : "")
                + "; black when n·v ≤ 0 (the course's 2019 rules)");
        if (!(nv > 0)) {
            steps.row("n·v", steps.num(nv) + "   (≤ 0: seen from behind its normal, the surface is black)");
            return Vec3.ZERO;
        }
        if (!mirrors()) {
            return steps.lightByLight(this, hit, ray);
        }
        // The lights' part alone: the same shader without its mirror term.
        Vec3 lights = steps.lightByLight(new ReflectionShader(name, brdf, diffuseColor, texture, Vec3.ZERO, specularColor, exponent),
                hit, ray);
        Vec3 weight = schlick(nv);
        steps.row("n·v", steps.num(nv));
        steps.row("R", steps.vec(weight) + "   (k_m = " + steps.vec(mirrorCoefficient) + ")");
        Vec3 d = v.negate();
        Vec3 lMirror = steps.mirror(hit, d.minus(hit.normal.times(2 * d.dot(hit.normal))));
        Vec3 total = shade(hit, ray, steps.context(), 0);
        steps.row("L", "lights + R ⊙ L_mirror = " + steps.vec(lights) + " + " + steps.vec(weight) + " ⊙ "
                + steps.vec(lMirror) + " = " + steps.vec(total));
        return total;
    }

    @Override
    public String toString() {
        return name;
    }
}
