package ray.numerics;

import java.util.List;
import ray.accuracy.Setting;
import ray.accuracy.Sweep;
import ray.accuracy.SweepProvider;
import ray.render.RayOffsets;
import ray.surface.Surface;

/**
 * The accuracy report's sweeps whose code must not ship (found by ServiceLoader through
 * META-INF/services in src/instructorTest/resources): float vs double intersection
 * ({@link FloatSurfaces}; with offsets sized for float's ε, and with double's to show why they
 * must be) and the textbook sphere with Cramer's rule vs the robust tests ({@link TextbookSurfaces}). {@code gradle accuracyReport} runs with the test classpath, so it has them.
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
                        List.of(Setting.framework("robust"), Setting.surfaces("textbook", InstructorSweeps::textbook)), true));
    }

    /** Every sphere by the textbook quadratic and every triangle by Cramer's rule: a student's first answers. */
    static Surface textbook(Surface root) {
        return TextbookSurfaces.withTriangles(TextbookSurfaces.withTextbookSpheres(root), TextbookTriangles.CRAMER);
    }
}
