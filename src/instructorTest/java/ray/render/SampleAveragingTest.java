package ray.render;

import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.scene.Scene;
import ray.shading.RGBNormals;
import ray.surface.Triangle;

/**
 * A pixel's value is the average of its samples (SampleGridTest checks where the samples are).
 * Instructor-only: it needs hits, so working camera, triangle and group code.
 */
public class SampleAveragingTest {
    @Test
    public void pixelIsTheAverageOfItsSamples() {
        // One pixel seeing x, y in [−0.5, 0.5]; its 2×2 samples are at x, y = ±0.25. A triangle covers
        // x ≤ 0 there (its long edge crosses y = ±0.25 near x = −50), so the two left samples see
        // RGBNormals of +z, (0.5, 0.5, 1), and the two right ones the background.
        Scene scene = TestScenes.scene(TestScenes.orthographicDown(v(0, 0, 5), 1, 1), 1, 1);
        Triangle left = new Triangle(v(-100, -100, 0), v(0, -100, 0), v(0, 100, 0));
        left.setShader(new RGBNormals());
        scene.addSurface(left.complete());
        scene.setBackColor(v(0.2, 0.4, 0.6));
        scene.complete();
        RenderResult result = new Renderer(scene, 4, 1).render();
        // ((0.5 + 0.2)/2, (0.5 + 0.4)/2, (1 + 0.6)/2)
        assertVec(v(0.35, 0.45, 0.8), result.image.get(0, 0), 1e-12);
    }
}
