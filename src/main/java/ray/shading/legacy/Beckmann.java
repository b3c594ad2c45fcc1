package ray.shading.legacy;

import ray.shading.MicrofacetDistribution;

/** {@code <brdf type="Beckmann">}: the Beckmann distribution, for a Microfacet shader. */
public class Beckmann extends MicrofacetBrdfElement {
    @Override
    public String distributionName() {
        return MicrofacetDistribution.BECKMANN;
    }
}
