package ray.accuracy;

import java.util.ArrayList;
import java.util.List;
import java.util.ServiceLoader;
import ray.accel.Acceleration;
import ray.render.RayOffsets;
import ray.render.SamplePattern;

/** The sweeps of the accuracy study: the framework's own and those a {@link SweepProvider} adds. */
public final class Sweeps {
    /** The samples-per-pixel points of the study unless asked otherwise. */
    public static final List<Integer> SAMPLES = List.of(1, 4, 16, 64, 256);
    /** Every sweep the full study has, in report order. */
    public static final List<String> ALL = List.of("samples", "arithmetic", "intersection", "fresnel", "masking", "offsets", "depth",
            "acceleration");
    /** The deepest setting of the depth sweep, its baseline: the course's limit of 12 hits along a path. */
    static final int DEEPEST = 12;
    /** The seed of the jittered points (the reference uses another, so its noise is independent). */
    static final long SEED = 1;

    private Sweeps() {
    }

    /** Regular grid and jittered at each count: the convergence study. */
    public static Sweep samples(List<Integer> counts) {
        List<Setting> settings = new ArrayList<>();
        for (int n : counts) {
            settings.add(Setting.sampled("grid " + n, n, SamplePattern.GRID));
        }
        for (int n : counts) {
            settings.add(Setting.sampled("jittered " + n, n, SamplePattern.jittered(SEED)));
        }
        return new Sweep("samples", "How fast does the error fall with samples per pixel, on the regular grid and jittered?",
                settings, false);
    }

    /** The framework's scaled offsets against pbrt's error-bound offsets, none and a fixed epsilon. */
    public static Sweep offsets() {
        return new Sweep("offsets", "Where do shadow and reflection rays start: what does each rule cost, and where does it leave acne?",
                List.of(Setting.offsets("offset scaled", RayOffsets.SCALED), Setting.offsets("offset error bound", RayOffsets.ERROR_BOUND),
                        Setting.offsets("offset fixed 1e-6", RayOffsets.FIXED), Setting.offsets("offset none", RayOffsets.NONE)), true);
    }

    /**
     * Paths of mirror rays cut after 12 hits (the course's limit, the baseline) and after 1 to 11:
     * what each level of mirror reflection costs in rays and time, and what stopping early leaves
     * out. Measured only on scenes that trace mirror rays.
     */
    public static Sweep depth() {
        List<Setting> settings = new ArrayList<>();
        settings.add(Setting.pathHits("depth " + DEEPEST, DEEPEST));
        for (int hits = 1; hits < DEEPEST; hits++) {
            settings.add(Setting.pathHits("depth " + hits, hits));
        }
        return new Sweep("depth", "How deep must mirror rays go: what does each bounce cost, and what does stopping early leave out?",
                settings, true);
    }

    /**
     * The framework's BVH and any-hit shadow rays against plain linear loops: a cost dimension with
     * no accuracy in it (the images are identical), so its whole effect is in the time column.
     */
    public static Sweep acceleration() {
        return new Sweep("acceleration", "What does the BVH save, at the same error (the image is the same)?",
                List.of(Setting.acceleration("bvh", Acceleration.BVH), Setting.acceleration("linear", Acceleration.NONE)), true);
    }

    /** The samples, offsets and acceleration sweeps, with the providers' sweeps between them, in {@link #ALL}'s order. */
    public static List<Sweep> available(List<Integer> counts) {
        List<Sweep> sweeps = new ArrayList<>();
        sweeps.add(samples(counts));
        for (SweepProvider provider : ServiceLoader.load(SweepProvider.class)) {
            sweeps.addAll(provider.sweeps());
        }
        sweeps.add(offsets());
        sweeps.add(depth());
        sweeps.add(acceleration());
        sweeps.sort((a, b) -> Integer.compare(order(a.name), order(b.name)));
        return sweeps;
    }

    /** The sweeps of {@link #ALL} that {@code sweeps} lacks (in a student's copy: arithmetic and intersection). */
    public static List<String> missing(List<Sweep> sweeps) {
        List<String> missing = new ArrayList<>(ALL);
        sweeps.forEach(s -> missing.remove(s.name));
        return missing;
    }

    private static int order(String name) {
        int k = ALL.indexOf(name);
        return k >= 0 ? k : ALL.size();
    }
}
