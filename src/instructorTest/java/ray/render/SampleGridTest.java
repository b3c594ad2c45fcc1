package ray.render;

import static org.junit.Assert.assertEquals;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.junit.Test;
import ray.scene.Scene;

/**
 * The pixel loop's sample positions: pixel (i, j), j from the bottom, with N samples asks the camera
 * for the n×n grid (i + (a + ½)/n)/nx, (j + (b + ½)/n)/ny, n = round(√N). That the pixel is the
 * average of its samples needs hits, so it is checked in the instructor's SampleAveragingTest.
 */
public class SampleGridTest {
    private static final double TOL = 1e-12;

    private static final Comparator<double[]> BY_U_THEN_V =
            Comparator.<double[]>comparingDouble(p -> p[0]).thenComparingDouble(p -> p[1]);

    private static List<double[]> askedBy(int width, int height, int samples, int threads) {
        RecordingCamera camera = new RecordingCamera();
        Scene scene = TestScenes.scene(camera, width, height);
        scene.complete();
        new Renderer(scene, samples, threads).render();
        List<double[]> asked = new ArrayList<>(camera.asked);
        asked.sort(BY_U_THEN_V);
        return asked;
    }

    private static List<double[]> grid(int width, int height, int n) {
        List<double[]> points = new ArrayList<>();
        for (int j = 0; j < height; j++) {
            for (int i = 0; i < width; i++) {
                for (int a = 0; a < n; a++) {
                    for (int b = 0; b < n; b++) {
                        points.add(new double[] {(i + (a + 0.5) / n) / width, (j + (b + 0.5) / n) / height});
                    }
                }
            }
        }
        points.sort(BY_U_THEN_V);
        return points;
    }

    private static void assertSamePoints(List<double[]> expected, List<double[]> actual) {
        assertEquals("number of camera rays", expected.size(), actual.size());
        for (int k = 0; k < expected.size(); k++) {
            assertEquals("u of sample " + k, expected.get(k)[0], actual.get(k)[0], TOL);
            assertEquals("v of sample " + k, expected.get(k)[1], actual.get(k)[1], TOL);
        }
    }

    @Test
    public void gridSideIsTheRoundedSquareRoot() {
        int[][] samplesAndSide = {{1, 1}, {2, 1}, {3, 2}, {4, 2}, {6, 2}, {7, 3}, {9, 3}, {16, 4}, {20, 4}, {21, 5}, {100, 10}};
        for (int[] c : samplesAndSide) {
            assertEquals("gridSide(" + c[0] + ")", c[1], Renderer.gridSide(c[0]));
        }
        assertEquals("never below one sample", 1, Renderer.gridSide(0));
    }

    @Test
    public void oneSampleAsksForEveryPixelCenter() {
        // A 3×2 image: u in {1/6, 1/2, 5/6}, v in {1/4, 3/4}.
        List<double[]> asked = askedBy(3, 2, 1, 1);
        assertSamePoints(grid(3, 2, 1), asked);
        assertEquals(1.0 / 6, asked.get(0)[0], TOL);
        assertEquals(0.25, asked.get(0)[1], TOL);
        assertEquals(5.0 / 6, asked.get(5)[0], TOL);
        assertEquals(0.75, asked.get(5)[1], TOL);
    }

    @Test
    public void fourSamplesAskForTheTwoByTwoGridInEachPixel() {
        List<double[]> asked = askedBy(3, 2, 4, 1);
        assertSamePoints(grid(3, 2, 2), asked);
        // The first column of samples: u = (0 + 0.25)/3, at v = (0 + 0.25)/2, (0 + 0.75)/2, (1 + 0.25)/2, (1 + 0.75)/2.
        double[] firstColumnV = {0.125, 0.375, 0.625, 0.875};
        for (int k = 0; k < 4; k++) {
            assertEquals(0.25 / 3, asked.get(k)[0], TOL);
            assertEquals(firstColumnV[k], asked.get(k)[1], TOL);
        }
    }

    @Test
    public void threeSamplesRoundToTheTwoByTwoGrid() {
        assertSamePoints(grid(2, 3, 2), askedBy(2, 3, 3, 1));
    }

    @Test
    public void nineSamplesUseAThreeByThreeGridWithManyThreads() {
        assertSamePoints(grid(4, 3, 3), askedBy(4, 3, 9, 3));
    }

    @Test
    public void zeroOverrideUsesTheScenesSamples() {
        RecordingCamera camera = new RecordingCamera();
        Scene scene = TestScenes.scene(camera, 2, 2);
        scene.setSamples(16);
        scene.complete();
        RenderResult result = new Renderer(scene, 0, 1).render();
        assertEquals(16, result.samplesPerPixel);
        assertEquals(4 * 16, camera.asked.size());

        camera.asked.clear();
        assertEquals("an explicit count overrides the scene", 1, new Renderer(scene, 1, 1).render().samplesPerPixel);
        assertEquals(4, camera.asked.size());
    }
}
