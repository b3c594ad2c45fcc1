package ray.shading;

import java.util.EnumSet;
import java.util.Set;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * A microfacet shader as a scene file writes it (the course's 2018–2019 {@code MicrofacetBeckmann}
 * and {@code MicrofacetGGX}, and the older {@code Microfacet} with a scene-level {@code <brdf>}): a
 * diffuse color or texture, the facets' color k_mf, the roughness α, the refractive index nt and a
 * mirror coefficient. Once loaded it is a {@link ReflectionShader} with a {@link MicrofacetBrdf}, under
 * either course: a microfacet model is a BRDF, and the course shaded it only as one (L = Σ f ⊙ I ·
 * max(0, n·l)/r², black seen from behind, a Schlick-weighted mirror term).
 */
public abstract class MicrofacetShader extends Shader {
    private Vec3 diffuseColor = Vec3.ZERO;
    private Vec3 microfacetColor = Vec3.ONE;
    private Texture texture;
    private Vec3 mirrorCoefficient = Vec3.ZERO;
    private double alpha;
    private double nt;

    /** ρd, 0 0 0 unless given (the course's default: a microfacet surface is all facets). */
    public void setDiffuseColor(Vec3 diffuseColor) {
        this.diffuseColor = diffuseColor;
    }

    /** k_mf, the color of the facets' reflection (1 1 1 unless given). */
    public void setMicrofacetColor(Vec3 microfacetColor) {
        this.microfacetColor = microfacetColor;
    }

    /** A texture whose color at each hit replaces ρd (never k_mf). */
    public void setTexture(Texture texture) {
        this.texture = texture;
    }

    /** k_m, each channel from 0 to 1, as for the course's other 2019 shaders. */
    public void setMirrorCoefficient(Vec3 mirrorCoefficient) {
        this.mirrorCoefficient = BrdfShader.checkedMirrorCoefficient(mirrorCoefficient);
    }

    /** α, the roughness: > 0; small is nearly a mirror. */
    public void setAlpha(double alpha) {
        this.alpha = alpha;
    }

    /** nt, the refractive index under the surface: > 0; 1 gives no facet reflection. */
    public void setNt(double nt) {
        this.nt = nt;
    }

    /** The distribution's name ("Beckmann", "GGX"). */
    protected abstract String distributionName();

    /** α as the scene gave it (0 when it gave none). */
    protected double alpha() {
        return alpha;
    }

    /** nt as the scene gave it (0 when it gave none). */
    protected double nt() {
        return nt;
    }

    /** Refuses a roughness or index that is missing, not positive or not finite, naming the element to give. */
    @Override
    public void complete() {
        check("alpha", alpha(), "a roughness > 0, such as 0.3");
        check("nt", nt(), "a refractive index > 0, such as 1.5");
    }

    private static void check(String element, double value, String expected) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(value == 0 ? "no <" + element + "> (or 0); expected " + expected
                    : element + " is " + value + "; expected " + expected);
        }
    }

    @Override
    public Vec3 getDiffuseColor() {
        return diffuseColor;
    }

    @Override
    public Texture getTexture() {
        return texture;
    }

    @Override
    public Set<Effect> effects() {
        return EnumSet.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR);
    }

    /** The shader it loads as, under any course: a {@link ReflectionShader} with the microfacet BRDF. */
    @Override
    public Shader forCourse(Course course) {
        MicrofacetBrdf brdf = new MicrofacetBrdf(microfacetColor, distributionName(), alpha(), nt());
        return new ReflectionShader(toString(), brdf, diffuseColor, texture, mirrorCoefficient, microfacetColor, null);
    }

    /** Shades as the shader it loads as (a scene's loader never leaves this one in place). */
    @Override
    public Vec3 shade(IntersectionRecord hit, Ray ray, ShadingContext context, int depth) {
        return forCourse(Course.Y2019).shade(hit, ray, context, depth);
    }
}
