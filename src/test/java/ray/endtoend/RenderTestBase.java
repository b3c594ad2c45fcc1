package ray.endtoend;

import static org.junit.Assert.fail;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Test;
import ray.image.ImageDiff;
import ray.image.PngReader;
import ray.testing.StudentTask;

/**
 * A graded render test: renders one shipped scene at its full size with your code and compares
 * it with the reference image in scenes/reference by {@link ImageDiff} (at most
 * {@link ImageDiff#MAX_SHARE} of the pixels may differ by more than
 * {@link ImageDiff#TOLERANCE_LEVELS} levels). A mismatch adds the scene to the report
 * build/reports/render-diff/index.html, with your image, the reference and a heat map.
 *
 * <p>Subclasses, one per task, give the scenes ({@link RenderScenes#TASKS}), the points and the rule.
 */
public abstract class RenderTestBase {
    /** A whole scene at full size takes about a second with the solution; a stuck loop is stopped here. */
    static final int TIMEOUT_SECONDS = 60;

    private final String scene;

    protected RenderTestBase(String scene) {
        this.scene = scene;
    }

    /** The task this class's scenes count toward. */
    protected abstract StudentTask task();

    @Test
    public void rendersLikeTheReference() throws Exception {
        Path file = RenderScenes.fileOf(scene);
        Path referenceFile = RenderScenes.referenceOf(scene);
        if (!Files.exists(file)) {
            fail("the scene " + file + " is missing (it is listed in RenderScenes.TASKS)");
        }
        if (!Files.exists(referenceFile)) {
            fail("no reference image " + referenceFile + " for " + file + "; the instructor makes them with gradle references");
        }
        BufferedImage reference = PngReader.read(referenceFile);
        BufferedImage yours = RenderScenes.render(file);
        ImageDiff.Result result = ImageDiff.compare(reference, yours);
        if (!result.passed()) {
            String report = RenderDiffReport.add(getClass(), scene, task(), result, yours, reference);
            fail(file + " does not look like " + referenceFile + ": " + result.summary()
                    + ".\n    See your image, the reference and where they differ in " + report);
        }
    }
}
