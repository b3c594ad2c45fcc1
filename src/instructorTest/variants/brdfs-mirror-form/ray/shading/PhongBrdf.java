package ray.shading;

import ray.math.Vec3;

/** Known wrong: Phong's original highlight, (r·v)^p with r the light mirrored about n, in place of Blinn's (n·h)^p. */
public class PhongBrdf extends PhongBrdfParameters {

    public PhongBrdf() {
    }

    public PhongBrdf(Vec3 specularColor, double exponent) {
        super(specularColor, exponent);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 r = n.times(2 * n.dot(l)).minus(l);
        return rhoD.times(1 / Math.PI).plus(getSpecularColor().times(Math.pow(Math.max(0, r.dot(v)), getExponent())));
    }
}
