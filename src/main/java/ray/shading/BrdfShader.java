package ray.shading;

import java.util.EnumSet;
import java.util.Set;
import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * What the framework keeps of the course's 2019 shader ({@link ReflectionShader}, whose light loop and
 * mirror term students write): its {@link Brdf}, diffuse color or texture, mirror coefficient k_m,
 * and, for what {@code ray1 trace} shows, the scene's name for it and its highlight's ks and p.
 * The loader makes one from a Lambertian or Phong element when a scene loads under 2019's
 * conventions ({@link Shader#forCourse}); it is never written in a scene file itself.
 */
public abstract class BrdfShader extends Shader {
    private String name = "ReflectionShader";
    private Brdf brdf;
    private Vec3 diffuseColor = Vec3.ONE;
    private Texture texture;
    private Vec3 mirrorCoefficient = Vec3.ZERO;
    /** ks, for the description; null for a shader without a highlight. */
    private Vec3 specularColor;
    /** p, for the description; NaN for a shader without a highlight. */
    private double exponent = Double.NaN;

    protected BrdfShader() {
    }

    /**
     * @param name          the scene's name for it ("Lambertian", "Phong"), which trace shows
     * @param specularColor ks and {@code exponent} p, for the description; null for a shader without a highlight
     */
    protected BrdfShader(String name, Brdf brdf, Vec3 diffuseColor, Texture texture, Vec3 mirrorCoefficient, Vec3 specularColor,
            Double exponent) {
        this.name = name;
        this.brdf = brdf;
        this.diffuseColor = diffuseColor;
        this.texture = texture;
        this.mirrorCoefficient = mirrorCoefficient;
        this.specularColor = specularColor;
        this.exponent = exponent == null ? Double.NaN : exponent;
    }

    /** The BRDF f(l, v) the lights are reflected by: {@code brdf().value(ρd, n, l, v)}. */
    public Brdf brdf() {
        return brdf;
    }

    /** Gives the shader another BRDF (the grader's worker, whose BRDF is asked of the judge). */
    public void setBrdf(Brdf brdf) {
        this.brdf = brdf;
    }

    /** {@code km} if each channel is from 0 to 1, as a scene's mirror coefficient must be; else a one-line error. */
    static Vec3 checkedMirrorCoefficient(Vec3 km) {
        for (int axis = 0; axis < 3; axis++) {
            double k = km.get(axis);
            if (!(k >= 0 && k <= 1)) {
                throw new IllegalArgumentException("mirrorCoefficient is " + km + "; expected three numbers from 0 to 1");
            }
        }
        return km;
    }

    /** k_m, each channel from 0 to 1: the mirror term's weight head on. */
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

    /** Gives the shader another texture (the grader's worker, whose texture color is the judge's). */
    public void setTexture(Texture texture) {
        this.texture = texture;
    }

    /** ρd at a hit: the texture's color there, or the diffuse color when there is no texture. */
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
        return Double.isNaN(exponent) ? null : exponent;
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
    private Vec3 schlick(double cosine) {
        double m = 1 - Math.min(1, cosine);
        double m5 = m * m * m * m * m;
        return new Vec3(mirrorCoefficient.x + (1 - mirrorCoefficient.x) * m5, mirrorCoefficient.y + (1 - mirrorCoefficient.y) * m5,
                mirrorCoefficient.z + (1 - mirrorCoefficient.z) * m5);
    }

    /** The back-face gate: whether the hit is seen from behind its shading normal (n·v ≤ 0, v toward the ray's origin). */
    private static boolean seenFromBehind(IntersectionRecord hit, Ray ray) {
        return !(hit.normal.dot(towardEye(ray)) > 0);
    }

    @Override
    public boolean evaluatesAt(IntersectionRecord hit, Ray ray) {
        return !seenFromBehind(hit, ray);
    }

    /** This shader with another mirror coefficient (k_m = 0: its lights' part alone). */
    private ReflectionShader withMirrorCoefficient(Vec3 km) {
        return new ReflectionShader(name, brdf, diffuseColor, texture, km, specularColor, getExponent());
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
        if (seenFromBehind(hit, ray)) {
            steps.row("n·v", steps.num(nv) + "   (≤ 0: seen from behind its normal, the surface is black)");
            return Vec3.ZERO;
        }
        if (!mirrors()) {
            return steps.lightByLight(this, hit, ray);
        }
        // The lights' part alone: the same shader without its mirror term.
        Vec3 lights = steps.lightByLight(withMirrorCoefficient(Vec3.ZERO), hit, ray);
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
