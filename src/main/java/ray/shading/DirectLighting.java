package ray.shading;

import java.util.EnumSet;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * What the framework keeps of a shader lit by point lights (a Lambertian's or a Phong's colors, its
 * texture and its 2019 mirror coefficient): L = Σ over unshadowed lights of I ⊙ f(kd, n, l, e) / r²,
 * where l is the unit vector to the light, r the distance to it and e the unit vector toward the eye.
 * The light loop itself, {@code shade}, is in the classes students open ({@link Lambertian},
 * {@link Phong}). The diffuse color kd is the shader's {@code diffuseColor}, or, when it has a
 * {@code texture}, the texture's color at the hit, which replaces it.
 */
public abstract class DirectLighting extends Shader {
    private Vec3 diffuseColor;
    private Texture texture;
    private Vec3 mirrorCoefficient = Vec3.ZERO;

    public void setDiffuseColor(Vec3 diffuseColor) {
        this.diffuseColor = diffuseColor;
    }

    /** The diffuse color given, or 1 1 1 (2017's default) when none was. */
    @Override
    public Vec3 getDiffuseColor() {
        return diffuseColor != null ? diffuseColor : Vec3.ONE;
    }

    /**
     * The 2019 mirror coefficient k_m, each channel from 0 to 1: the weight of a mirror ray head on,
     * which Schlick's approximation raises toward 1 at grazing angles. 2017 has no mirror term.
     */
    @OnlyInCourse("2019")
    public void setMirrorCoefficient(Vec3 mirrorCoefficient) {
        this.mirrorCoefficient = BrdfShader.checkedMirrorCoefficient(mirrorCoefficient);
    }

    public Vec3 getMirrorCoefficient() {
        return mirrorCoefficient;
    }

    /** The BRDF this shader is under the 2019 conventions. */
    protected abstract Brdf brdf2019();

    /** The diffuse color under the 2019 conventions when the scene gives none. */
    protected abstract Vec3 defaultDiffuseColor2019();

    /** Under 2019, a {@link ReflectionShader} with this shader's BRDF, colors, texture and mirror coefficient. */
    @Override
    public Shader forCourse(Course course) {
        if (course != Course.Y2019) {
            return this;
        }
        return new ReflectionShader(toString(), brdf2019(), diffuseColor != null ? diffuseColor : defaultDiffuseColor2019(),
                texture, mirrorCoefficient, getSpecularColor(), getExponent());
    }

    /** A texture whose color at each hit replaces the diffuse color. */
    public void setTexture(Texture texture) {
        this.texture = texture;
    }

    /** The texture, or null. */
    @Override
    public Texture getTexture() {
        return texture;
    }

    /** kd at a hit: the texture's color there, or the diffuse color when there is no texture. */
    @Override
    public Vec3 diffuseColorAt(IntersectionRecord hit) {
        return texture != null ? texture.colorAt(hit) : getDiffuseColor();
    }

    @Override
    public Set<Effect> effects() {
        Set<Effect> effects = EnumSet.of(Effect.LIGHTING, Effect.SHADOWS);
        if (texture != null) {
            effects.add(Effect.TEXTURES);
        }
        return effects;
    }

    @Override
    public Vec3 explain(IntersectionRecord hit, Ray ray, ShadingSteps steps) {
        steps.line((getSpecularColor() != null && getExponent() != null
                ? "L = Σ over lights of (kd ⊙ I · max(0, n·l) + ks ⊙ I · max(0, n·h)^p) / r²"
                : "L = Σ over lights of kd ⊙ I · max(0, n·l) / r²") + ", without the lights whose shadow ray is blocked");
        return steps.lightByLight(this, hit, ray);
    }
}
