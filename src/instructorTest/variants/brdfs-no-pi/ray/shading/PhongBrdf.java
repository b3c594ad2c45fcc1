package ray.shading;

import ray.math.Vec3;

/** Known wrong: no π: f = ρd + ks·max(0, n·h)^p. */
public class PhongBrdf extends PhongBrdfParameters {

    public PhongBrdf() {
    }

    public PhongBrdf(Vec3 specularColor, double exponent) {
        super(specularColor, exponent);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 h = l.plus(v).normalized();
        return rhoD.plus(getSpecularColor().times(Math.pow(Math.max(0, n.dot(h)), getExponent())));
    }
}
