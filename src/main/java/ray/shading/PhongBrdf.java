package ray.shading;

import ray.math.Vec3;

/**
 * The course's 2019 "modified Blinn–Phong" BRDF, f = ρd/π + ks·max(0, n·h)^p with the half vector
 * h = normalize(l + v). As the course wrote it, the highlight has no normalisation factor (its
 * references rule out both (p+2)/2π and (p+8)/8π), and since it is part of f it is weighted by
 * max(0, n·l) like the diffuse term.
 */
public final class PhongBrdf implements Brdf {
    private final Vec3 specularColor;
    private final double exponent;

    public PhongBrdf(Vec3 specularColor, double exponent) {
        this.specularColor = specularColor;
        this.exponent = exponent;
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 sum = l.plus(v);
        // l = −v (a light straight behind the viewer's line) has no half vector; such a light is
        // below the surface whenever the viewer is above it, so it gets no highlight.
        double highlight = sum.lengthSquared() == 0 ? 0 : Math.pow(Math.max(0, n.dot(sum.normalized())), exponent);
        return rhoD.times(1 / Math.PI).plus(specularColor.times(highlight));
    }

    @Override
    public String formula() {
        return "ρd/π + ks·max(0, n·h)^p";
    }
}
