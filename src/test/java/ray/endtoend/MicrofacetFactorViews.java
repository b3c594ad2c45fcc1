package ray.endtoend;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import ray.image.ImageDiff;
import ray.image.PngReader;
import ray.image.PngWriter;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.shading.MicrofacetFactor;

/**
 * For a microfacet scene whose render differs from its reference: each factor of the microfacet BRDF
 * (D, F and G1(l)·G1(v)) rendered alone with the student's code, as {@code ray1 render --microfacet-term}
 * renders it, beside the reference's view of the same factor, so the report says which factor parts
 * from the reference.
 */
final class MicrofacetFactorViews {
    /** One factor's view: the student's and the reference's images and how they compare. */
    record View(MicrofacetFactor factor, BufferedImage yours, BufferedImage reference, ImageDiff.Result result) {
    }

    private MicrofacetFactorViews() {
    }

    /** The factor views of {@code scene} (loaded from a file), for each factor whose reference view is in {@code referenceFolder}. */
    static List<View> of(Scene scene, Path referenceFolder, String name) throws IOException {
        List<View> views = new ArrayList<>();
        for (MicrofacetFactor factor : MicrofacetFactor.values()) {
            Path reference = MicrofacetFactor.referenceView(referenceFolder, name, factor);
            if (!Files.isRegularFile(reference)) {
                continue;
            }
            Scene alone = scene.reload(options -> options.withMicrofacetFactor(factor));
            BufferedImage yours = PngWriter.toBufferedImage(new Renderer(alone, 0, 0).render().image, alone.getExposure());
            BufferedImage expected = PngReader.read(reference);
            views.add(new View(factor, yours, expected, ImageDiff.compare(expected, yours)));
        }
        return views;
    }

    /** "Each microfacet factor alone (ray1 render --microfacet-term D, F or G): D differs (…), F and G match their references." */
    static String line(List<View> views) {
        List<String> parts = new ArrayList<>();
        for (View view : views) {
            parts.add(view.factor().name() + (view.result().passed() ? " matches its reference" : " differs (" + view.result().summary() + ")"));
        }
        return "Each microfacet factor alone (ray1 render --microfacet-term D, F or G): " + String.join("; ", parts) + ".";
    }
}
