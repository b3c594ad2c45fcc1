package ray.shading;

/** The scene files' {@code <shader type="MicrofacetGGX">}: a microfacet shader with the GGX distribution. */
public class MicrofacetGGX extends MicrofacetShader {
    @Override
    protected String distributionName() {
        return MicrofacetDistribution.GGX;
    }
}
