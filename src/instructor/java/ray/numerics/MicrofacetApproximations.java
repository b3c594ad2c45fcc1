package ray.numerics;

import org.apache.commons.math3.special.Erf;
import ray.math.Vec3;
import ray.shading.Brdf;
import ray.shading.MicrofacetBrdfParameters;

/**
 * The course's microfacet BRDF with one factor computed another way, for the accuracy report's
 * sweeps: Schlick's Fresnel approximation R0 + (1 − R0)(1 − c)^5 with R0 = ((nt − 1)/(nt + 1))² in place
 * of the exact dielectric factor, or Beckmann's exact Smith masking term in place of the course's
 * rational fit. Everything else is the BRDF's own: its D, its other factor, k_mf and ρd/π. Not
 * shipped: it restates the students' BRDF.
 */
final class MicrofacetApproximations implements Brdf {
    /** Which factor is computed another way. */
    enum Change {
        SCHLICK_FRESNEL, SMITH_MASKING
    }

    private final MicrofacetBrdfParameters brdf;
    private final Change change;

    MicrofacetApproximations(MicrofacetBrdfParameters brdf, Change change) {
        this.brdf = brdf;
        this.change = change;
    }

    /** {@code brdf} with {@code change} when it is a microfacet BRDF; any other BRDF as it is. */
    static Brdf of(Brdf brdf, Change change) {
        return brdf instanceof MicrofacetBrdfParameters ? new MicrofacetApproximations((MicrofacetBrdfParameters) brdf, change) : brdf;
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        double nl = n.dot(l);
        double nv = n.dot(v);
        if (!(nl > 0) || !(nv > 0)) {
            return Vec3.ZERO;
        }
        Vec3 h = l.plus(v).normalized();
        double c = Math.abs(l.dot(h));
        double f = change == Change.SCHLICK_FRESNEL ? schlick(brdf.fresnel().getNt(), c) : brdf.fresnel().reflectance(c);
        double d = brdf.distribution().normalDistribution(n, h);
        boolean smith = change == Change.SMITH_MASKING && brdf.distribution().name().equals("Beckmann");
        double gl = smith ? smithBeckmann(brdf.distribution().getAlpha(), l, n, h) : brdf.distribution().masking(l, n, h);
        double gv = smith ? smithBeckmann(brdf.distribution().getAlpha(), v, n, h) : brdf.distribution().masking(v, n, h);
        return rhoD.times(1 / Math.PI).plus(brdf.getMicrofacetColor().times(f * d * (gl / nl) * (gv / nv) / 4));
    }

    /** Schlick's approximation of the dielectric Fresnel factor. */
    static double schlick(double nt, double cosine) {
        double r0 = (nt - 1) / (nt + 1);
        r0 *= r0;
        double m = 1 - cosine;
        return r0 + (1 - r0) * m * m * m * m * m;
    }

    /**
     * Beckmann's Smith masking term without the rational fit (Walter et al. 2007, eq. 25 before its
     * approximation): with a = 1/(α tanθ), G1 = 2 / (1 + erf(a) + exp(−a²)/(a√π)); 1 along the normal.
     */
    static double smithBeckmann(double alpha, Vec3 x, Vec3 n, Vec3 h) {
        double xn = x.dot(n);
        if (!(x.dot(h) * xn > 0)) {
            return 0;
        }
        double sine = x.cross(n).length();
        if (sine == 0) {
            return 1;
        }
        double a = Math.abs(xn) / (alpha * sine);
        return 2 / (1 + Erf.erf(a) + Math.exp(-a * a) / (a * Math.sqrt(Math.PI)));
    }

    @Override
    public String formula() {
        return brdf.formula() + (change == Change.SCHLICK_FRESNEL ? ", Schlick's F" : ", exact Smith G1 (erf)");
    }
}
