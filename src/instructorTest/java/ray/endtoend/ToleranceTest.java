package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.function.Function;
import org.junit.Test;
import ray.image.ImageDiff;
import ray.image.PngReader;
import ray.scene.SceneFiles;

/**
 * {@link ImageDiff}'s constants on real renders against the shipped references: each defect a
 * student might make (a camera off by half a pixel, an upside-down image, missing shadows) fails
 * with at least twice the allowed share, and the solution and correct variants of it (other
 * thread counts, the textbook sphere formula, Möller–Trumbore triangles, one-ulp rounding
 * differences) pass with a quarter of it to spare. Uses the cheapest scenes that show each
 * defect; {@link ToleranceSurvey} measures all of them.
 */
public class ToleranceTest {
    private static ImageDiff.Result compare(String scene, Function<Path, BufferedImage> variant) throws Exception {
        BufferedImage reference = PngReader.read(RenderScenes.referenceOf(scene));
        return ImageDiff.compare(reference, variant.apply(RenderScenes.fileOf(scene)));
    }

    private static void assertFailsClearly(String what, String scene, ImageDiff.Result r) {
        assertFalse(what + " on " + scene + " must fail: " + r, r.passed());
        assertTrue(what + " on " + scene + " must fail by a margin (at least twice MAX_SHARE): " + r,
                r.differingShare() >= 2 * ImageDiff.MAX_SHARE);
    }

    private static void assertPassesClearly(String what, String scene, ImageDiff.Result r) {
        assertTrue(what + " on " + scene + " must pass: " + r, r.passed());
        assertTrue(what + " on " + scene + " must pass by a margin (at most a quarter of MAX_SHARE): " + r,
                r.differingShare() <= ImageDiff.MAX_SHARE / 4);
    }

    /** two-boxes and one-sphere are the scenes where half a pixel shows least (0.92% and 1.1% beyond 2 levels). */
    @Test
    public void halfPixelCameraFails() throws Exception {
        for (String scene : new String[] {"two-boxes", "one-sphere", "wire-box"}) {
            assertFailsClearly("a camera off by half a pixel", scene, compare(scene, Variants::halfPixelCamera));
        }
    }

    /** Flipping the reference itself is the correct image written bottom row first. */
    @Test
    public void upsideDownImageFailsOnEveryScene() throws Exception {
        for (Path file : RenderScenes.sceneFiles()) {
            String scene = SceneFiles.nameOf(file);
            BufferedImage reference = PngReader.read(RenderScenes.referenceOf(scene));
            assertFailsClearly("the image upside down", scene, ImageDiff.compare(reference, Variants.flipped(reference)));
        }
    }

    /** wire-box and wire-box-ortho are where missing shadows show least (1.7% beyond 2 levels). */
    @Test
    public void missingShadowsFail() throws Exception {
        for (String scene : new String[] {"two-boxes", "wire-box", "wire-box-ortho"}) {
            assertFailsClearly("a render without shadows", scene, compare(scene, Variants::withoutShadows));
        }
    }

    /** The scene rendered now by the solution, with 1 and with 3 threads, is the reference. */
    @Test
    public void solutionPassesWithAnyThreadCount() throws Exception {
        for (String scene : new String[] {"one-sphere", "two-boxes", "wire-box", "rgb-normals"}) {
            ImageDiff.Result one = compare(scene, f -> Variants.solution(f, 1));
            assertPassesClearly("the solution with 1 thread", scene, one);
            // Java's arithmetic is strict, so on the machine that made the references the match is exact.
            assertEquals(scene + ": " + one, 0, one.maxDifference());
            assertPassesClearly("the solution with 3 threads", scene, compare(scene, f -> Variants.solution(f, 3)));
        }
    }

    @Test
    public void correctVariantsPass() throws Exception {
        for (String scene : new String[] {"one-sphere", "wire-box", "rgb-normals"}) {
            assertPassesClearly("textbook sphere formula", scene, compare(scene, Variants::textbookSpheres));
        }
        for (String scene : new String[] {"two-boxes", "wire-box", "rgb-normals"}) {
            assertPassesClearly("Möller–Trumbore triangles", scene, compare(scene, Variants::mollerTrumboreTriangles));
        }
        for (String scene : new String[] {"one-sphere-phong", "two-boxes"}) {
            ImageDiff.Result r = compare(scene, Variants::ulpJitter);
            assertPassesClearly("radiance off by one ulp, StrictMath.pow", scene, r);
            assertTrue(scene + ": " + r, r.maxDifference() <= 1);
        }
    }
}
