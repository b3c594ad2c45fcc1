package ray.shading.legacy;

/**
 * The older course scenes' scene-level {@code <brdf name="…" type="Beckmann">} (or {@code "GGX"}):
 * a microfacet distribution's roughness α and refractive index nt, which a
 * {@code <shader type="Microfacet">} refers to. It holds numbers only; the shader checks them.
 */
public abstract class MicrofacetBrdfElement {
    private double alpha;
    private double nt;

    public void setAlpha(double alpha) {
        this.alpha = alpha;
    }

    public void setNt(double nt) {
        this.nt = nt;
    }

    public double getAlpha() {
        return alpha;
    }

    public double getNt() {
        return nt;
    }

    /** The distribution's name, as {@link ray.shading.MicrofacetDistribution#named} reads it. */
    public abstract String distributionName();

    @Override
    public String toString() {
        return distributionName() + " BRDF";
    }
}
