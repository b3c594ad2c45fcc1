package ray.shading;

import java.util.EnumSet;
import java.util.Set;
import ray.math.Vec3;

/**
 * What the framework keeps of a Blinn–Phong shader ({@link Phong}, whose light loop students write):
 * its diffuse color or texture, its specular color ks and exponent p, and how the 2019 conventions
 * turn it into a BRDF ({@link PhongBrdf}).
 */
public abstract class PhongShader extends DirectLighting {
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
}
