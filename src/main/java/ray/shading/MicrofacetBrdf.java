package ray.shading;

import ray.math.Vec3;

/**
 * The course's microfacet BRDF (Walter et al. 2007, reflection only): a diffuse part ρd/π and the
 * facets' reflection k_mf·F·D·G1(l)·G1(v)/(4|n·l||n·v|). Its k_mf, distribution (D, G1) and Fresnel
 * factor (F) are kept by MicrofacetBrdfParameters.
 */
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
        // TODO(Task 11): return the microfacet BRDF's value, combining the Fresnel factor, D and G1.
        //   Return f(l, v): a matte part (as the Lambertian BRDF's) plus the light the surface's tiny mirror
        //   facets reflect from l to v: those whose normal is the half vector, as many as D says, the share
        //   F that a facet reflects, and the shares G1 that neither direction's view is hidden.
        //   Conventions (the reference images depend on them):
        //   - rhoD is the diffuse reflectance, per channel; n, l and v are unit vectors (the normal, toward
        //     the light, toward the eye); h = normalize(l + v).
        //   - f = ρd/π + k_mf · F(|l·h|) · D(h) · G1(l, h) · G1(v, h) / (4 |n·l| |n·v|), with
        //     k_mf = getMicrofacetColor(), F = fresnel().reflectance, D = distribution().normalDistribution
        //     and G1 = distribution().masking. No cosine: the shader multiplies f by max(0, n·l).
        //   - f = 0 (all of it) when l or v is on or below the surface.
        //   - Never NaN or infinite at grazing angles: divide each G1 by its own cosine first.
        // HINTS steps
        //   1) If the light or the eye is not above the surface, return black.
        //   2) Find the half vector, the unit vector halfway between l and v.
        //   3) Ask for the Fresnel factor at the cosine between l and the half vector, D of the half vector,
        //      and the masking term of each direction divided by that direction's cosine with the normal.
        //   4) Multiply them together and divide by 4; return the diffuse reflectance over π plus the
        //      microfacet color times that.
        // HINTS formulas
        //   1) if n·l ≤ 0 or n·v ≤ 0, return Vec3.ZERO.
        //   2) h = (l + v) / |l + v|.
        //   3) F = fresnel().reflectance(|l·h|), D = distribution().normalDistribution(n, h),
        //      g = distribution().masking(l, n, h) / (n·l) · distribution().masking(v, n, h) / (n·v).
        //   4) f = ρd/π + k_mf · F · D · g / 4.
        // END HINTS
        // BEGIN SOLUTION
        double nl = n.dot(l);
        double nv = n.dot(v);
        if (!(nl > 0) || !(nv > 0)) {
            return Vec3.ZERO;
        }
        Vec3 h = l.plus(v).normalized();
        double f = fresnel().reflectance(Math.abs(l.dot(h)));
        double d = distribution().normalDistribution(n, h);
        // Each masking term over its own cosine: both stay finite as a direction grazes the surface,
        // where the product of the two cosines alone could underflow to 0.
        double g = distribution().masking(l, n, h) / nl * (distribution().masking(v, n, h) / nv);
        return rhoD.times(1 / Math.PI).plus(getMicrofacetColor().times(f * d * g / 4));
        // END SOLUTION
        // STUB: return Vec3.ZERO;
    }
}
