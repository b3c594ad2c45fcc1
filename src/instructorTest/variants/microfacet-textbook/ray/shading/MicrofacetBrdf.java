package ray.shading;

import ray.math.Vec3;

/** Correct: the textbook form, F·D·G1(l)·G1(v) over the product 4|n·l||n·v|, the half vector by hand. */
public class MicrofacetBrdf extends MicrofacetBrdfParameters {

    public MicrofacetBrdf() {
    }

    public MicrofacetBrdf(Vec3 microfacetColor, String distributionName, double alpha, double nt) {
        super(microfacetColor, distributionName, alpha, nt);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        double nl = n.dot(l);
        double nv = n.dot(v);
        if (nl <= 0 || nv <= 0) {
            return new Vec3(0, 0, 0);
        }
        double hx = l.x + v.x;
        double hy = l.y + v.y;
        double hz = l.z + v.z;
        double length = Math.sqrt(hx * hx + hy * hy + hz * hz);
        Vec3 h = new Vec3(hx / length, hy / length, hz / length);
        double specular = fresnel().reflectance(Math.abs(l.dot(h))) * distribution().normalDistribution(n, h)
                * distribution().masking(l, n, h) * distribution().masking(v, n, h) / (4 * Math.abs(nl) * Math.abs(nv));
        Vec3 k = getMicrofacetColor();
        return new Vec3(rhoD.x / Math.PI + k.x * specular, rhoD.y / Math.PI + k.y * specular, rhoD.z / Math.PI + k.z * specular);
    }
}
