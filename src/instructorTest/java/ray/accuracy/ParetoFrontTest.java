package ray.accuracy;

import static org.junit.Assert.assertEquals;

import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import org.junit.Test;

public class ParetoFrontTest {
    /** {time, error} with a label for messages. */
    private static double[] run(double time, double error) {
        return new double[] {time, error};
    }

    private static List<double[]> front(double[]... runs) {
        return ParetoFront.of(Arrays.asList(runs), r -> r[0], r -> r[1]);
    }

    @Test
    public void keepsTheRunsNoOtherBeatsOnTimeAndError() {
        double[] fastRough = run(1, 0.5);
        double[] slowerBetter = run(2, 0.2);
        double[] slowerWorse = run(3, 0.3); // beaten by slowerBetter
        double[] slowestBest = run(8, 0.01);
        double[] sameTimeWorse = run(2, 0.4); // beaten by slowerBetter
        List<double[]> front = front(slowestBest, slowerWorse, fastRough, sameTimeWorse, slowerBetter);
        assertEquals(Arrays.asList(fastRough, slowerBetter, slowestBest), front);
    }

    @Test
    public void equalRunsKeepOneAndAnEmptyListHasNoFront() {
        double[] a = run(1, 0.1);
        double[] b = run(1, 0.1);
        assertEquals(1, front(a, b).size());
        assertEquals(Collections.emptyList(), front());
    }

    @Test
    public void seededRandomRunsMatchTheDefinition() {
        java.util.Random random = new java.util.Random(11);
        double[][] runs = new double[200][];
        for (int k = 0; k < runs.length; k++) {
            runs[k] = run(random.nextInt(50), random.nextInt(50));
        }
        List<double[]> front = front(runs);
        for (double[] r : runs) {
            boolean dominated = false;
            for (double[] other : runs) {
                dominated |= other[0] <= r[0] && other[1] <= r[1] && (other[0] < r[0] || other[1] < r[1]);
            }
            boolean onFront = front.stream().anyMatch(f -> f[0] == r[0] && f[1] == r[1]);
            assertEquals("run (" + r[0] + ", " + r[1] + ")", !dominated, onFront);
        }
    }
}
