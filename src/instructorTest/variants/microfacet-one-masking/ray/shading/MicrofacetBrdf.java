package ray.shading;

import ray.math.Vec3;

/** Known wrong: the masking term of the light's direction only, G1(l), without G1(v). */
public class MicrofacetBrdf extends MicrofacetBrdfParameters {

    public MicrofacetBrdf() {
    }

    /**
     * @param distributionName "Beckmann" or "GGX", with roughness {@code alpha}
     * @param nt               the Fresnel factor's refractive index
     */
    public MicrofacetBrdf(Vec3 microfacetColor, String distributionName, double alpha, double nt) {
        super(microfacetColor, distributionName, alpha, nt);
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        double nl = n.dot(l);
        double nv = n.dot(v);
        if (!(nl > 0) || !(nv > 0)) {
            return Vec3.ZERO;
        }
        Vec3 h = l.plus(v).normalized();
        double f = fresnel().reflectance(Math.abs(l.dot(h)));
        double d = distribution().normalDistribution(n, h);
        double g = distribution().masking(l, n, h) / nl / nv;
        return rhoD.times(1 / Math.PI).plus(getMicrofacetColor().times(f * d * g / 4));
    }
}
