package ray.accuracy;

/**
 * The least-squares line through (log x, log y): y ≈ c·x^slope. For error against samples per
 * pixel the slope is the convergence rate: about −½ for independent random samples, steeper for
 * stratified ones, and about −1 (per sample, n² of them) for the regular grid on a smooth image,
 * where it is the midpoint rule. Natural logarithms; the slope does not depend on the base.
 */
public final class PowerLawFit {
    public final double slope;
    /** c, the value of the fitted line at x = 1. */
    public final double coefficient;
    /** The coefficient of determination of the fit in log–log space (1 for an exact power law). */
    public final double rSquared;

    private PowerLawFit(double slope, double coefficient, double rSquared) {
        this.slope = slope;
        this.coefficient = coefficient;
        this.rSquared = rSquared;
    }

    /** Fits y ≈ c·x^slope; needs at least two distinct positive x and positive y values. */
    public static PowerLawFit of(double[] x, double[] y) {
        if (x.length != y.length) {
            throw new IllegalArgumentException(x.length + " x values but " + y.length + " y values");
        }
        int n = x.length;
        double meanX = 0;
        double meanY = 0;
        for (int k = 0; k < n; k++) {
            if (!(x[k] > 0 && y[k] > 0) || Double.isInfinite(x[k]) || Double.isInfinite(y[k])) {
                throw new IllegalArgumentException("a power law needs positive finite values, got (" + x[k] + ", " + y[k] + ")");
            }
            meanX += Math.log(x[k]) / n;
            meanY += Math.log(y[k]) / n;
        }
        double sxx = 0;
        double sxy = 0;
        double syy = 0;
        for (int k = 0; k < n; k++) {
            double dx = Math.log(x[k]) - meanX;
            double dy = Math.log(y[k]) - meanY;
            sxx += dx * dx;
            sxy += dx * dy;
            syy += dy * dy;
        }
        if (n < 2 || sxx == 0) {
            throw new IllegalArgumentException("a power law needs at least two different x values");
        }
        double slope = sxy / sxx;
        double rSquared = syy == 0 ? 1 : sxy * sxy / (sxx * syy);
        return new PowerLawFit(slope, Math.exp(meanY - slope * meanX), rSquared);
    }

    /** The fitted line's value at x. */
    public double at(double x) {
        return coefficient * Math.pow(x, slope);
    }
}
