package ray.shading;

import java.util.EnumSet;
import java.util.Set;
import ray.math.Vec3;

/**
 * Blinn–Phong: L = Σ (kd ⊙ I · max(0, n·l) + ks ⊙ I · max(0, n·h)^p) / r², with the half vector
 * h = normalize(l + e). As in the course's 2017 reference renderer, the specular term is not gated by n·l,
 * and a texture replaces kd only. Under 2019's conventions it is {@link PhongBrdf} instead.
 */
public class Phong extends DirectLighting {
    private Vec3 specularColor = Vec3.ONE;
    private double exponent = 1.0;

    public void setSpecularColor(Vec3 specularColor) {
        this.specularColor = specularColor;
    }

    public void setExponent(double exponent) {
        if (!(exponent >= 0) || Double.isInfinite(exponent)) {
            throw new IllegalArgumentException("exponent is " + exponent + "; expected a number ≥ 0");
        }
        this.exponent = exponent;
    }

    @Override
    public Vec3 getSpecularColor() {
        return specularColor;
    }

    @Override
    public Double getExponent() {
        return exponent;
    }

    /** Each light's reflectance includes one specular term. */
    @Override
    public Set<Effect> effects() {
        Set<Effect> effects = EnumSet.copyOf(super.effects());
        effects.add(Effect.SPECULAR);
        return effects;
    }

    @Override
    protected Brdf brdf2019() {
        return new PhongBrdf(specularColor, exponent);
    }

    @Override
    protected Vec3 defaultDiffuseColor2019() {
        return Vec3.ONE;
    }

    @Override
    protected Vec3 reflectance(Vec3 kd, Vec3 normal, Vec3 toLight, Vec3 toEye) {
        Vec3 half = toLight.plus(toEye).normalized();
        double diffuse = Math.max(0, normal.dot(toLight));
        double specular = Math.pow(Math.max(0, normal.dot(half)), exponent);
        return kd.times(diffuse).plus(specularColor.times(specular));
    }
}
