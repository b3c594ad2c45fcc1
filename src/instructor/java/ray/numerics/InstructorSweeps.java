package ray.numerics;

import java.util.List;
import ray.accuracy.Setting;
import ray.accuracy.Sweep;
import ray.accuracy.SweepProvider;
import ray.render.RayOffsets;
import ray.scene.Scene;
import ray.surface.Surface;

/**
 * The accuracy report's sweeps whose code must not ship (found by ServiceLoader through
 * META-INF/services in src/instructorTest/resources): float vs double intersection
 * ({@link FloatSurfaces}; with offsets sized for float's ε, and with double's to show why they
 * must be), the textbook sphere with Cramer's rule vs the robust tests ({@link TextbookSurfaces}), and
 * the microfacet BRDF's exact Fresnel factor and rational Beckmann masking term vs Schlick's
 * approximation and the exact erf form ({@link MicrofacetApproximations}; scenes with a microfacet shader only). {@code gradle accuracyReport} runs with the test classpath, so it has them.
 */
public final class InstructorSweeps implements SweepProvider {
    @Override
    public List<Sweep> sweeps() {
        return List.of(
                new Sweep("arithmetic", "What does float arithmetic in the intersection tests save, and what does it cost the image?",
                        List.of(Setting.framework("double"),
                                Setting.surfaces("float", FloatSurfaces::of).withOffsets("float", RayOffsets.SCALED_FOR_FLOAT),
                                Setting.surfaces("float, double's offsets", FloatSurfaces::of)), true),
                new Sweep("intersection", "What do the robust sphere and watertight triangle tests cost over the textbook ones, and what do they fix?",
                        List.of(Setting.framework("robust"), Setting.surfaces("textbook", InstructorSweeps::textbook)), true),
                new Sweep("fresnel", "What does Schlick's approximation of the Fresnel factor save over the exact one, and what does it change?",
                        List.of(Setting.framework("Fresnel exact"), Setting.reloaded("Fresnel Schlick",
                                options -> options.withBrdfs(b -> MicrofacetApproximations.of(b, MicrofacetApproximations.Change.SCHLICK_FRESNEL)))),
                        true, Scene::hasMicrofacetShader),
                new Sweep("masking", "What does the course's rational fit of Beckmann's masking term save over the exact erf form, and what does it change?",
                        List.of(Setting.framework("G1 rational"), Setting.reloaded("G1 erf",
                                options -> options.withBrdfs(b -> MicrofacetApproximations.of(b, MicrofacetApproximations.Change.SMITH_MASKING)))),
                        true, Scene::hasMicrofacetShader));
    }

    /** Every sphere by the textbook quadratic and every triangle by Cramer's rule: a student's first answers. */
    static Surface textbook(Surface root) {
        return TextbookSurfaces.withTriangles(TextbookSurfaces.withTextbookSpheres(root), TextbookTriangles.CRAMER);
    }
}
