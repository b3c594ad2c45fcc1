package ray.shading.legacy;

import ray.shading.MicrofacetDistribution;

/** {@code <brdf type="GGX">}: the GGX distribution, for a Microfacet shader. */
public class GGX extends MicrofacetBrdfElement {
    @Override
    public String distributionName() {
        return MicrofacetDistribution.GGX;
    }
}
