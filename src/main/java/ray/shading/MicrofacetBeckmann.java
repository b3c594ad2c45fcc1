package ray.shading;

/** The scene files' {@code <shader type="MicrofacetBeckmann">}: a microfacet shader with the Beckmann distribution. */
public class MicrofacetBeckmann extends MicrofacetShader {
    @Override
    protected String distributionName() {
        return MicrofacetDistribution.BECKMANN;
    }
}
