package ray.shading;

import java.nio.file.Path;
import ray.math.Vec3;

/**
 * One factor of the microfacet BRDF, rendered alone as the course's debug images were: each pixel
 * is exposure · k_mf ⊙ X · I · max(0, n·l)/r² with X the factor, so a wrong factor shows on its own
 * picture. G is both masking terms together, G1(l)·G1(v).
 */
public enum MicrofacetFactor {
    D("D(h), the distribution of facet normals"),
    F("F(|l·h|), the Fresnel factor"),
    G("G1(l)·G1(v), the masking terms");

    /** What the factor is, for descriptions and messages. */
    public final String description;

    MicrofacetFactor(String description) {
        this.description = description;
    }

    /** The factor for unit n, l and v above the surface, as {@code brdf}'s own distribution and Fresnel factor compute it. */
    public double of(MicrofacetBrdfParameters brdf, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 h = l.plus(v).normalized();
        switch (this) {
            case D:
                return brdf.distribution().normalDistribution(n, h);
            case F:
                return brdf.fresnel().reflectance(Math.abs(l.dot(h)));
            default:
                return brdf.distribution().masking(l, n, h) * brdf.distribution().masking(v, n, h);
        }
    }

    /**
     * Where the reference image of a scene's view of this factor is kept, beside the scene's own
     * reference in {@code referenceFolder}: {@code factors/<scene>-<factor>.png}.
     */
    public static Path referenceView(Path referenceFolder, String scene, MicrofacetFactor factor) {
        return referenceFolder.resolve("factors").resolve(scene + "-" + factor.name() + ".png");
    }

    /** "D", "d", "F", "G" as a command line gives it; an IllegalArgumentException naming the choices otherwise. */
    public static MicrofacetFactor of(String name) {
        for (MicrofacetFactor factor : values()) {
            if (factor.name().equalsIgnoreCase(name.strip())) {
                return factor;
            }
        }
        throw new IllegalArgumentException("no microfacet factor is called '" + name + "'; expected D, F or G");
    }
}
