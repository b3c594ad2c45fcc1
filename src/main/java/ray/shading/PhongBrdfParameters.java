package ray.shading;

import ray.math.Vec3;

/**
 * What the framework keeps of the course's 2019 Phong BRDF ({@link PhongBrdf}, whose {@code value}
 * students write): the specular color ks and the exponent p that the Phong shader of the scene gave,
 * and the formula as {@code ray1 trace} writes it.
 */
public abstract class PhongBrdfParameters implements Brdf {
    private Vec3 specularColor = Vec3.ONE;
    private double exponent = 1;

    protected PhongBrdfParameters() {
    }

    protected PhongBrdfParameters(Vec3 specularColor, double exponent) {
        this.specularColor = specularColor;
        this.exponent = exponent;
    }

    /** ks: the highlight's color, per channel. */
    public Vec3 getSpecularColor() {
        return specularColor;
    }

    /** p: how narrow the highlight is. */
    public double getExponent() {
        return exponent;
    }

    @Override
    public String formula() {
        return "ρd/π + ks·max(0, n·h)^p";
    }
}
