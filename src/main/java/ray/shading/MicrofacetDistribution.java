package ray.shading;

import ray.math.Vec3;

/**
 * A distribution of microfacet normals, as the course's microfacet BRDF (Walter et al. 2007,
 * "Microfacet models for refraction through rough surfaces") uses one: its roughness α, and two
 * functions of it that students write, the distribution D(h) of facet normals and Smith's masking
 * term G1(x, h), the share of facets with normal h that direction x sees. {@link BeckmannDistribution}
 * and {@link GgxDistribution} are the course's two.
 */
public abstract class MicrofacetDistribution {
    /** The names scene files give the course's two distributions. */
    public static final String BECKMANN = "Beckmann";
    public static final String GGX = "GGX";
    private double alpha = 1;

    /** A distribution whose roughness is set later (the grader's copy, whose fields are copied in). */
    protected MicrofacetDistribution() {
    }

    /** @param alpha the roughness α: the slopes' spread, a number > 0 (small: nearly a mirror) */
    protected MicrofacetDistribution(double alpha) {
        if (!(alpha > 0) || Double.isInfinite(alpha)) {
            throw new IllegalArgumentException("alpha is " + alpha + "; expected a roughness > 0");
        }
        this.alpha = alpha;
    }

    /** The distribution a scene names ("Beckmann" or "GGX"), with roughness {@code alpha}. */
    public static MicrofacetDistribution named(String name, double alpha) {
        if (name.equals(BECKMANN)) {
            return new BeckmannDistribution(alpha);
        }
        if (name.equals(GGX)) {
            return new GgxDistribution(alpha);
        }
        throw new IllegalArgumentException("no microfacet distribution is called " + name + "; expected "
                + BECKMANN + " or " + GGX);
    }

    /** α, the roughness. */
    public double getAlpha() {
        return alpha;
    }

    /**
     * D(h): the density of facet normals at the unit vector {@code h}, per unit of solid angle and
     * projected onto the surface (so that D(h)·(n·h) integrates to 1 over the hemisphere), for a
     * surface with unit normal {@code n}. Zero for h below the surface.
     */
    public abstract double normalDistribution(Vec3 n, Vec3 h);

    /**
     * G1(x, h): the share, from 0 to 1, of the facets with normal {@code h} that the unit direction
     * {@code x} sees unhidden by other facets, on a surface with unit normal {@code n}. Zero when x
     * is on the other side of the facet from the surface's side it is on.
     */
    public abstract double masking(Vec3 x, Vec3 n, Vec3 h);

    /** The distribution's name, as scene files and {@code ray1 trace} write it: "Beckmann", "GGX". */
    public abstract String name();

    /** Checks nothing: its constructor has checked its roughness. */
    public void complete() {
    }

    @Override
    public String toString() {
        return name() + " (α = " + alpha + ")";
    }
}
