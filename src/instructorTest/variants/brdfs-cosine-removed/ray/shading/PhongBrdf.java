package ray.shading;

import ray.math.Vec3;

/**
 * Known wrong: no cosine on the specular term: the highlight divided by n·l, so that the shader's
 * max(0, n·l) cancels on it as in 2017's formula, where only the diffuse term had the cosine.
 */
public class PhongBrdf extends PhongBrdfParameters {

    public PhongBrdf() {
    }

    public PhongBrdf(Vec3 specularColor, double exponent) {
        super(specularColor, exponent);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 h = l.plus(v).normalized();
        double nl = n.dot(l);
        double highlight = nl > 0 ? Math.pow(Math.max(0, n.dot(h)), getExponent()) / nl : 0;
        return rhoD.times(1 / Math.PI).plus(getSpecularColor().times(highlight));
    }
}
