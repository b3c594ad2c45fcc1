package ray.accuracy;

import java.util.Arrays;
import java.util.function.Supplier;

/**
 * Wall time of repeated runs of the same work: the median (robust to one run disturbed by the JIT
 * or the machine) and the spread, min to max. The accuracy report times every choice this way,
 * three runs or more.
 */
public final class Timing {
    public final int runs;
    public final double medianSeconds;
    public final double minSeconds;
    public final double maxSeconds;

    private Timing(double[] seconds) {
        double[] sorted = seconds.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        runs = n;
        medianSeconds = n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
        minSeconds = sorted[0];
        maxSeconds = sorted[n - 1];
    }

    /** The timing of runs that took these many seconds each. */
    public static Timing of(double... seconds) {
        if (seconds.length == 0) {
            throw new IllegalArgumentException("a timing needs at least one run");
        }
        for (double s : seconds) {
            if (!(s >= 0) || Double.isInfinite(s)) {
                throw new IllegalArgumentException("a run cannot take " + s + " seconds");
            }
        }
        return new Timing(seconds);
    }

    /** A result and how long it took to make, over several runs. */
    public static final class Timed<T> {
        public final T result;
        public final Timing timing;

        Timed(T result, Timing timing) {
            this.result = result;
            this.timing = timing;
        }
    }

    /** Runs {@code work} {@code runs} times; the result is the last run's (each run must make the same). */
    public static <T> Timed<T> measure(int runs, Supplier<T> work) {
        if (runs < 1) {
            throw new IllegalArgumentException("runs must be at least 1, got " + runs);
        }
        double[] seconds = new double[runs];
        T result = null;
        for (int k = 0; k < runs; k++) {
            long start = System.nanoTime();
            result = work.get();
            seconds[k] = (System.nanoTime() - start) / 1e9;
        }
        return new Timed<>(result, new Timing(seconds));
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "%.3f s (%.3f–%.3f s, %d runs)", medianSeconds, minSeconds, maxSeconds, runs);
    }
}
