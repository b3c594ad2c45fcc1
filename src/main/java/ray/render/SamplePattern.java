package ray.render;

/**
 * Where a pixel's n×n samples fall. Sample (a, b) of pixel (i, j) lies in the stratum
 * [a/n, (a+1)/n) × [b/n, (b+1)/n) of the pixel:
 * <ul>
 * <li>{@link #GRID}, the default and what the reference images use: at the stratum's center,
 * ((a + ½)/n, (b + ½)/n);</li>
 * <li>{@link #jittered(long)}: at a uniformly random point of the stratum (stratified sampling,
 * Cook 1986). The random numbers are a hash of (seed, i, j, a, b, axis), not a stream, so a
 * pixel's samples do not depend on which thread renders it or in what order: the image is the
 * same for any thread count, and the same seed gives the same image.</li>
 * </ul>
 * Jittering trades the grid's aliasing (regular stair-steps on edges) for noise, which shrinks
 * as samples grow and averages toward the true pixel integral.
 */
public final class SamplePattern {
    public static final SamplePattern GRID = new SamplePattern(false, 0);

    private final boolean jittered;
    private final long seed;
    /** mix(seed), the first step of every hash, made once rather than per sample. */
    private final long seedHash;

    private SamplePattern(boolean jittered, long seed) {
        this.jittered = jittered;
        this.seed = seed;
        this.seedHash = mix(seed);
    }

    /** Jittered samples whose random offsets are fixed by {@code seed}. */
    public static SamplePattern jittered(long seed) {
        return new SamplePattern(true, seed);
    }

    public boolean isJittered() {
        return jittered;
    }

    public long seed() {
        return seed;
    }

    /** The x position in pixel (i, j), in [0, 1), of sample (a, b) of an n×n grid. */
    public double x(int i, int j, int a, int b, int n) {
        return (a + (jittered ? uniform(i, j, a, b, 0) : 0.5)) / n;
    }

    /** The y position in pixel (i, j), in [0, 1), of sample (a, b) of an n×n grid. */
    public double y(int i, int j, int a, int b, int n) {
        return (b + (jittered ? uniform(i, j, a, b, 1) : 0.5)) / n;
    }

    /**
     * A number in [0, 1) that looks uniformly random and depends only on its arguments: the
     * SplitMix64 finalizer (Steele, Lea and Flood, "Fast splittable pseudorandom number
     * generators", OOPSLA 2014) applied once per argument, its top 53 bits as a double.
     */
    private double uniform(int i, int j, int a, int b, int axis) {
        long h = mix(seedHash ^ i);
        h = mix(h ^ j);
        h = mix(h ^ a);
        h = mix(h ^ b);
        h = mix(h ^ axis);
        return (h >>> 11) * 0x1p-53;
    }

    private static long mix(long z) {
        z += 0x9e3779b97f4a7c15L;
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    /** "grid", or "jittered (seed S)". */
    public String describe() {
        return jittered ? "jittered (seed " + seed + ")" : "grid";
    }

    @Override
    public String toString() {
        return describe();
    }
}
