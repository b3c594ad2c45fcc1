package ray.accuracy;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.Random;
import org.junit.Test;

public class PowerLawFitTest {
    @Test
    public void anExactPowerLawGivesItsExponentAndCoefficient() {
        double[] samples = {1, 4, 16, 64, 256};
        double[] error = new double[samples.length];
        for (int k = 0; k < samples.length; k++) {
            error[k] = 0.3 * Math.pow(samples[k], -0.5);
        }
        PowerLawFit fit = PowerLawFit.of(samples, error);
        assertEquals(-0.5, fit.slope, 1e-12);
        assertEquals(0.3, fit.coefficient, 1e-12);
        assertEquals(1, fit.rSquared, 1e-12);
        assertEquals(0.3 / 32, fit.at(1024), 1e-12);
    }

    @Test
    public void seededNoiseAroundASlopeIsFitCloseToIt() {
        // y = 2·x^−1 times a log-normal factor (σ = 0.05), at 40 points over three decades: the
        // slope's standard error is about 0.05/√(40·var(log x)) ≈ 0.004.
        Random random = new Random(7);
        double[] x = new double[40];
        double[] y = new double[40];
        for (int k = 0; k < x.length; k++) {
            x[k] = Math.pow(10, 3.0 * k / (x.length - 1));
            y[k] = 2 / x[k] * Math.exp(0.05 * random.nextGaussian());
        }
        PowerLawFit fit = PowerLawFit.of(x, y);
        assertEquals(-1, fit.slope, 0.02);
        assertTrue("r² " + fit.rSquared, fit.rSquared > 0.99 && fit.rSquared < 1);
    }

    @Test
    public void zeroErrorsAndSingleXValuesCannotBeFit() {
        expectError(new double[] {1, 4}, new double[] {0.1, 0}, "a power law needs positive finite values, got (4.0, 0.0)");
        expectError(new double[] {4, 4}, new double[] {0.1, 0.2}, "a power law needs at least two different x values");
        expectError(new double[] {1}, new double[] {0.1, 0.2}, "1 x values but 2 y values");
    }

    private static void expectError(double[] x, double[] y, String message) {
        try {
            PowerLawFit.of(x, y);
            fail("expected: " + message);
        } catch (IllegalArgumentException e) {
            assertEquals(message, e.getMessage());
        }
    }
}
