package ray.shading;

import ray.math.Vec3;

/**
 * What the framework keeps of the course's microfacet BRDF ({@link MicrofacetBrdf}, whose
 * {@code value} students write): the microfacet color k_mf, which distribution of facet normals it
 * uses (D and G1) with its roughness α, and the refractive index nt of its Fresnel factor F; and the
 * formula as {@code ray1 trace} writes it. It keeps the distribution by name and numbers rather than as
 * an object, and makes the objects where they are asked for, so a copy of it (the grader's) makes
 * its own.
 */
public abstract class MicrofacetBrdfParameters implements Brdf {
    private Vec3 microfacetColor = Vec3.ONE;
    private String distributionName = MicrofacetDistribution.BECKMANN;
    private double alpha = 1;
    private double nt = 1.5;
    private MicrofacetDistribution distribution;
    private Fresnel fresnel;

    protected MicrofacetBrdfParameters() {
    }

    /**
     * @param distributionName {@code "Beckmann"} or {@code "GGX"}
     * @param alpha            the distribution's roughness, > 0
     * @param nt               the Fresnel factor's refractive index, > 0
     */
    protected MicrofacetBrdfParameters(Vec3 microfacetColor, String distributionName, double alpha, double nt) {
        this.microfacetColor = microfacetColor;
        this.distributionName = distributionName;
        this.alpha = alpha;
        this.nt = nt;
        distribution();
        fresnel();
    }

    /** k_mf: the color of the facets' reflection, per channel. */
    public Vec3 getMicrofacetColor() {
        return microfacetColor;
    }

    /** D and G1: {@code distribution().normalDistribution(n, h)} and {@code distribution().masking(x, n, h)}. */
    public MicrofacetDistribution distribution() {
        if (distribution == null) {
            distribution = MicrofacetDistribution.named(distributionName, alpha);
        }
        return distribution;
    }

    /** F: {@code fresnel().reflectance(cosine)}. */
    public Fresnel fresnel() {
        if (fresnel == null) {
            fresnel = new Fresnel(nt);
        }
        return fresnel;
    }

    /** The formula with its numbers: "ρd/π + k_mf·F·D·G1(l)·G1(v) / (4|n·l||n·v|), Beckmann α = 0.7, nt = 2, k_mf = (0.2, 0.3, 0.8)". */
    @Override
    public String formula() {
        return "ρd/π + k_mf·F·D·G1(l)·G1(v) / (4|n·l||n·v|), " + distributionName + " α = " + number(alpha) + ", nt = " + number(nt)
                + ", k_mf = " + microfacetColor.format(MicrofacetBrdfParameters::number);
    }

    /** A scene's number as it was written (the loader reads them as float): 0.7, 2. */
    private static String number(double x) {
        String s = String.valueOf((float) x);
        return s.endsWith(".0") ? s.substring(0, s.length() - 2) : s;
    }
}
