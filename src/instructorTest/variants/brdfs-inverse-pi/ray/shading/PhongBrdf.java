package ray.shading;

import ray.math.Vec3;

/** Correct: the diffuse part from the Lambertian BRDF, an early return below the surface, Math.pow. */
public class PhongBrdf extends PhongBrdfParameters {

    public PhongBrdf() {
    }

    public PhongBrdf(Vec3 specularColor, double exponent) {
        super(specularColor, exponent);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 diffuse = new LambertianBrdf().value(rhoD, n, l, v);
        Vec3 h = l.plus(v).normalized();
        double nh = n.dot(h);
        if (nh <= 0) {
            return diffuse;
        }
        return diffuse.plus(getSpecularColor().times(Math.pow(nh, getExponent())));
    }
}
