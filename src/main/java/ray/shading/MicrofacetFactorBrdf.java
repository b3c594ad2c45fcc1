package ray.shading;

import ray.math.Vec3;

/**
 * A microfacet BRDF's debug view ({@link MicrofacetFactor}): in place of f, k_mf times one factor,
 * with no diffuse part and no 1/(4|n·l||n·v|), and 0 with the light or the eye below the surface.
 */
public final class MicrofacetFactorBrdf implements Brdf {
    private final MicrofacetBrdfParameters brdf;
    private final MicrofacetFactor factor;

    public MicrofacetFactorBrdf(MicrofacetBrdfParameters brdf, MicrofacetFactor factor) {
        this.brdf = brdf;
        this.factor = factor;
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        if (!(n.dot(l) > 0) || !(n.dot(v) > 0)) {
            return Vec3.ZERO;
        }
        return brdf.getMicrofacetColor().times(factor.of(brdf, n, l, v));
    }

    @Override
    public String formula() {
        return "k_mf · " + factor.name() + " alone (the view of " + factor.description + ")";
    }
}
