package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.junit.Test;
import ray.scene.Scene;

/**
 * Jittered (stratified) sampling: every sample lies in its own cell of the pixel's n×n grid, at a
 * position fixed by the seed and the pixel alone (so the same for any thread count), and spread
 * uniformly within the cell.
 */
public class JitteredSamplingTest {
    private static final int WIDTH = 7;
    private static final int HEIGHT = 5;

    private static List<double[]> askedBy(int samples, SamplePattern pattern, int threads) {
        RecordingCamera camera = new RecordingCamera();
        Scene scene = TestScenes.scene(camera, WIDTH, HEIGHT);
        scene.complete();
        new Renderer(RenderPlan.of(scene, samples, pattern), threads).render();
        List<double[]> asked = new ArrayList<>(camera.asked);
        asked.sort(Comparator.<double[]>comparingDouble(p -> p[0]).thenComparingDouble(p -> p[1]));
        return asked;
    }

    @Test
    public void everyCellOfEveryPixelGetsExactlyOneSample() {
        int n = 3;
        List<double[]> asked = askedBy(n * n, SamplePattern.jittered(1), 1);
        assertEquals(WIDTH * HEIGHT * n * n, asked.size());
        int[][][][] count = new int[WIDTH][HEIGHT][n][n];
        for (double[] p : asked) {
            double x = p[0] * WIDTH;
            double y = p[1] * HEIGHT;
            int i = (int) Math.floor(x);
            int j = (int) Math.floor(y);
            count[i][j][(int) Math.floor((x - i) * n)][(int) Math.floor((y - j) * n)]++;
        }
        for (int i = 0; i < WIDTH; i++) {
            for (int j = 0; j < HEIGHT; j++) {
                for (int a = 0; a < n; a++) {
                    for (int b = 0; b < n; b++) {
                        assertEquals("samples in cell (" + a + ", " + b + ") of pixel (" + i + ", " + j + ")", 1, count[i][j][a][b]);
                    }
                }
            }
        }
    }

    @Test
    public void theSamplesDependOnTheSeedAndThePixelOnly() {
        List<double[]> one = askedBy(4, SamplePattern.jittered(42), 1);
        for (int threads : new int[] {2, 5}) {
            List<double[]> many = askedBy(4, SamplePattern.jittered(42), threads);
            for (int k = 0; k < one.size(); k++) {
                assertEquals("u of sample " + k + " with " + threads + " threads", one.get(k)[0], many.get(k)[0], 0);
                assertEquals("v of sample " + k + " with " + threads + " threads", one.get(k)[1], many.get(k)[1], 0);
            }
        }
        List<double[]> otherSeed = askedBy(4, SamplePattern.jittered(43), 1);
        List<double[]> grid = askedBy(4, SamplePattern.GRID, 1);
        int sameAsOtherSeed = 0;
        int sameAsGrid = 0;
        for (int k = 0; k < one.size(); k++) {
            sameAsOtherSeed += one.get(k)[0] == otherSeed.get(k)[0] ? 1 : 0;
            sameAsGrid += one.get(k)[0] == grid.get(k)[0] ? 1 : 0;
        }
        assertEquals("another seed moves every sample", 0, sameAsOtherSeed);
        assertEquals("jittered samples are off the cell centers", 0, sameAsGrid);
    }

    @Test
    public void offsetsWithinTheCellAreUniform() {
        // 16 samples in each of 35 pixels, two axes: 1,120 offsets. Uniform on [0, 1) has mean ½ and
        // variance 1/12; ten equal bins each hold a tenth. The bounds are about 5 standard deviations.
        SamplePattern pattern = SamplePattern.jittered(2026);
        List<Double> offsets = new ArrayList<>();
        int n = 4;
        for (int i = 0; i < WIDTH; i++) {
            for (int j = 0; j < HEIGHT; j++) {
                for (int a = 0; a < n; a++) {
                    for (int b = 0; b < n; b++) {
                        offsets.add(pattern.x(i, j, a, b, n) * n - a);
                        offsets.add(pattern.y(i, j, a, b, n) * n - b);
                    }
                }
            }
        }
        double sum = 0;
        double sumSquares = 0;
        int[] bins = new int[10];
        for (double o : offsets) {
            assertTrue("offset " + o + " in [0, 1)", o >= 0 && o < 1);
            sum += o;
            sumSquares += (o - 0.5) * (o - 0.5);
            bins[(int) (o * 10)]++;
        }
        int count = offsets.size();
        assertEquals("mean", 0.5, sum / count, 5 * Math.sqrt(1.0 / 12 / count));
        assertEquals("variance", 1.0 / 12, sumSquares / count, 0.015);
        for (int bin : bins) {
            assertEquals("share in a tenth of the cell", 0.1, (double) bin / count, 5 * Math.sqrt(0.09 / count));
        }
    }

    @Test
    public void theGridPutsEverySampleAtItsCellCenterAndIsTheDefault() {
        for (int n = 1; n <= 4; n++) {
            for (int a = 0; a < n; a++) {
                assertEquals((a + 0.5) / n, SamplePattern.GRID.x(3, 2, a, 0, n), 0);
                assertEquals((a + 0.5) / n, SamplePattern.GRID.y(3, 2, 0, a, n), 0);
            }
        }
        Scene scene = TestScenes.scene(new RecordingCamera(), WIDTH, HEIGHT);
        scene.complete();
        assertEquals(SamplePattern.GRID, RenderPlan.of(scene, 4).pattern());
        assertEquals("grid", SamplePattern.GRID.describe());
        assertEquals("jittered (seed 9)", SamplePattern.jittered(9).describe());
        assertNotEquals(SamplePattern.GRID.describe(), SamplePattern.jittered(0).describe());
    }
}
