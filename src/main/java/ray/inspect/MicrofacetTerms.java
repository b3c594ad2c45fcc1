package ray.inspect;

import ray.math.Vec3;
import ray.shading.BrdfShader;
import ray.shading.MicrofacetBrdfParameters;
import ray.shading.MicrofacetDistribution;
import ray.shading.Shader;

/**
 * One light's microfacet factors at a hit, for {@code ray1 trace} and the explore page: the half
 * vector, F, D, G1(l) and G1(v) as the shader's own distribution and Fresnel factor compute them,
 * and the facets' share k_mf ⊙ I · F·D·G1(l)·G1(v)/(4 |n·l||n·v|) · max(0, n·l)/r² that they make
 * together. The trace compares the shader's result with this, so a BRDF that combines correct
 * factors wrongly shows; each factor's own check is the unit tests' (the trace restates no formula).
 */
final class MicrofacetTerms {
    final Vec3 h;
    /** |l·h|, the cosine F is evaluated at. */
    final double lh;
    /** n·v, the eye's cosine in the denominator. */
    final double nv;
    final double fresnel;
    final double distribution;
    final double maskingL;
    final double maskingV;
    /** The facets' share of the light, or zero where the light or the eye is below the surface. */
    final Vec3 specular;
    /** What one of the factors threw, or null. */
    final String error;
    final String distributionClass;
    final double alpha;
    final double nt;

    private MicrofacetTerms(Vec3 h, double lh, double nv, double fresnel, double distribution, double maskingL, double maskingV, Vec3 specular,
            String error, String distributionClass, double alpha, double nt) {
        this.h = h;
        this.lh = lh;
        this.nv = nv;
        this.fresnel = fresnel;
        this.distribution = distribution;
        this.maskingL = maskingL;
        this.maskingV = maskingV;
        this.specular = specular;
        this.error = error;
        this.distributionClass = distributionClass;
        this.alpha = alpha;
        this.nt = nt;
    }

    /**
     * The factors of {@code shader}'s microfacet BRDF for unit {@code n}, {@code l} and {@code e} (toward
     * the eye), a light of {@code intensity} at squared distance {@code r2}; null for a shader without one.
     */
    static MicrofacetTerms of(Shader shader, Vec3 n, Vec3 l, Vec3 e, Vec3 intensity, double r2) {
        if (!(shader instanceof BrdfShader) || !(((BrdfShader) shader).brdf() instanceof MicrofacetBrdfParameters)) {
            return null;
        }
        MicrofacetBrdfParameters brdf = (MicrofacetBrdfParameters) ((BrdfShader) shader).brdf();
        MicrofacetDistribution d = brdf.distribution();
        String name = d.getClass().getSimpleName();
        Vec3 h = l.plus(e).normalized();
        double lh = Math.abs(l.dot(h));
        double nl = n.dot(l);
        double nv = n.dot(e);
        try {
            double f = brdf.fresnel().reflectance(lh);
            double dh = d.normalDistribution(n, h);
            double gl = d.masking(l, n, h);
            double gv = d.masking(e, n, h);
            Vec3 specular = !(nl > 0) || !(nv > 0) ? Vec3.ZERO
                    : brdf.getMicrofacetColor().times(intensity).times(f * dh * (gl / nl) * (gv / nv) / 4 * nl / r2);
            return new MicrofacetTerms(h, lh, nv, f, dh, gl, gv, specular, null, name, d.getAlpha(), brdf.fresnel().getNt());
        } catch (RuntimeException | StackOverflowError t) { // the student's factors: shown, never the trace's end
            return new MicrofacetTerms(h, lh, nv, Double.NaN, Double.NaN, Double.NaN, Double.NaN, null, "a factor throws " + t, name,
                    d.getAlpha(), brdf.fresnel().getNt());
        }
    }
}
