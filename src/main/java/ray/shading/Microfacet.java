package ray.shading;

import ray.shading.legacy.MicrofacetBrdfElement;

/**
 * The older course scenes' microfacet shader: {@code <shader type="Microfacet">} whose distribution,
 * roughness and refractive index come from a scene-level {@code <brdf type="Beckmann">} (or
 * {@code "GGX"}) it refers to with {@code <brdf ref="…"/>}. It shades as {@link MicrofacetBeckmann}
 * or {@link MicrofacetGGX} with the same numbers.
 */
public class Microfacet extends MicrofacetShader {
    private MicrofacetBrdfElement brdf;

    public void setBrdf(MicrofacetBrdfElement brdf) {
        this.brdf = brdf;
    }

    /** Refused: this form's roughness belongs to its {@code <brdf>}. */
    @Override
    public void setAlpha(double alpha) {
        throw new IllegalArgumentException("a Microfacet shader takes its alpha from the <brdf> it refers to; give <alpha> there");
    }

    /** Refused: this form's refractive index belongs to its {@code <brdf>}. */
    @Override
    public void setNt(double nt) {
        throw new IllegalArgumentException("a Microfacet shader takes its nt from the <brdf> it refers to; give <nt> there");
    }

    @Override
    public void complete() {
        if (brdf == null) {
            throw new IllegalArgumentException("no <brdf>; expected <brdf ref=\"…\"/> naming a scene-level <brdf type=\"Beckmann\"> or \"GGX\"");
        }
        super.complete();
    }

    @Override
    protected String distributionName() {
        return brdf.distributionName();
    }

    @Override
    protected double alpha() {
        return brdf.getAlpha();
    }

    @Override
    protected double nt() {
        return brdf.getNt();
    }
}
