package ray.accuracy;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import ray.image.Image;
import ray.image.ImageDiff;
import ray.image.ImageError;
import ray.image.PngWriter;
import ray.render.PixelWindow;
import ray.render.RenderPlan;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.render.SamplePattern;
import ray.scene.Scene;
import ray.shading.Effect;

/**
 * Renders one scene over every sweep and measures each setting: wall time (median of repeated
 * runs), rays, error against a converged reference and, for choice sweeps, defects against the
 * sweep's baseline.
 *
 * <p>Time and error are measured on a window of the image (by default the 64×64 window with the
 * most edges, where sampling matters most): 256 samples per pixel and a 1024-sample reference of a
 * whole image would take the mesh scenes tens of minutes on the linear closest-hit loop, and the
 * window's pixels are bit for bit those of a whole-image render. Defects, which can be anywhere,
 * are counted on the whole image.
 */
public final class AccuracyStudy {
    public static final int WINDOW_SIZE = 64;
    public static final int REFERENCE_SAMPLES = 1024;
    public static final int RUNS = 3;
    /** The reference's jitter seed: not the sweep's, so that the reference's noise is independent of every point's. */
    static final long REFERENCE_SEED = 0x5eed_2026L;
    /** Short renders are repeated until their runs add up to this many seconds (at most {@link #MAX_RUNS}), for a steadier median. */
    static final double MIN_TOTAL_SECONDS = 0.5;
    static final int MAX_RUNS = 500;
    /** Untimed runs first, until they add up to this many seconds (at least one): the JIT compiles the setting's code meanwhile. */
    static final double WARM_UP_SECONDS = 0.1;

    private final List<Integer> samples;
    private final int windowSize;
    private final PixelWindow window;
    private final int referenceSamples;
    private final int runs;
    private final int threads;
    private final Consumer<String> log;

    /**
     * @param samples          the samples sweep's counts
     * @param window           the window to measure, or null for the busiest of {@code windowSize}
     * @param referenceSamples samples per pixel of the jittered reference
     * @param runs             timed runs per setting, at least 3 for a median with a spread
     * @param threads          threads of the timed renders, 0 for one per core (the reference and whole-image renders use every core)
     * @param log              told one line per finished setting
     */
    public AccuracyStudy(List<Integer> samples, int windowSize, PixelWindow window, int referenceSamples, int runs,
            int threads, Consumer<String> log) {
        for (int n : samples) {
            if (n < 1) {
                throw new IllegalArgumentException("samples per pixel must be at least 1, got " + n);
            }
            if (n >= referenceSamples) {
                throw new IllegalArgumentException("the reference (" + referenceSamples
                        + " samples per pixel) must have more samples than every point of the sweep, which has " + n);
            }
        }
        if (windowSize < 1 || runs < 1 || threads < 0) {
            throw new IllegalArgumentException("the window size and runs must be positive and threads ≥ 0");
        }
        this.samples = List.copyOf(samples);
        this.windowSize = windowSize;
        this.window = window;
        this.referenceSamples = referenceSamples;
        this.runs = runs;
        this.threads = threads;
        this.log = log;
    }

    public SceneStudy study(Scene scene) {
        String name = scene.getName();
        double exposure = scene.getExposure();
        List<Sweep> available = Sweeps.available(samples);
        List<String> missing = Sweeps.missing(available);
        // The depth sweep's settings differ only where mirror rays are traced.
        boolean mirrors = RenderPlan.of(scene).runs(Effect.REFLECTION);
        List<Sweep> sweeps = new ArrayList<>(available);
        sweeps.removeIf(s -> s.name.equals("depth") && !mirrors);
        sweeps.removeIf(s -> !s.appliesTo(scene));
        PixelWindow part = window;
        if (part == null) {
            Image preview = render(RenderPlan.of(scene)).image;
            part = WindowChooser.busiest(preview, exposure, windowSize);
        }
        RenderPlan referencePlan = RenderPlan.of(scene, referenceSamples, SamplePattern.jittered(REFERENCE_SEED)).withWindow(part);
        RenderResult reference = render(referencePlan);
        log.accept(name + ": window " + part + ", reference " + referenceSamples + " spp in " + seconds(reference.seconds));
        List<Run> results = new ArrayList<>();
        for (Sweep sweep : sweeps) {
            Image baselineImage = null;
            for (Setting setting : sweep.settings) {
                RenderPlan plan = setting.plan(scene);
                Timing.Timed<RenderResult> timed = timed(plan.withWindow(part));
                RenderResult result = timed.result;
                double defects = Double.NaN;
                BufferedImage defectMap = null;
                if (sweep.hasBaseline) {
                    Image whole = render(plan).image;
                    if (baselineImage == null) {
                        baselineImage = whole;
                    }
                    defects = ImageError.of(whole, baselineImage, exposure).visibleShare;
                    if (defects > 0) {
                        defectMap = ImageDiff.compare(PngWriter.toBufferedImage(baselineImage, exposure),
                                PngWriter.toBufferedImage(whole, exposure), 0, 0).heatMap();
                    }
                }
                Run run = new Run(sweep.name, setting, timed.timing, result.rays.total(),
                        ImageError.of(result.image, reference.image, exposure), result.image, defects, defectMap);
                results.add(run);
                log.accept(name + ": " + setting.label + ": " + timed.timing + ", RMSE " + String.format(java.util.Locale.ROOT,
                        "%.3g", run.error.rmse) + (sweep.hasBaseline ? String.format(java.util.Locale.ROOT, ", defects %.3f%%",
                        100 * defects) : ""));
            }
        }
        return new SceneStudy(name, scene.getWidth(), scene.getHeight(), exposure, scene.getSamples(), part,
                referenceSamples, reference.seconds, reference.image, sweeps, missing, results);
    }

    /** An untimed render on every core. */
    private static RenderResult render(RenderPlan plan) {
        return new Renderer(plan, 0).render();
    }

    /**
     * Untimed runs first (the JIT's compilation of this setting's code would count otherwise),
     * then {@link #runs} timed ones, more for a render so short that the clock's and the
     * machine's noise would dominate.
     */
    private Timing.Timed<RenderResult> timed(RenderPlan plan) {
        long start = System.nanoTime();
        int warmUps = 0;
        double lastWarmUp = 0;
        while (warmUps == 0 || (System.nanoTime() - start) / 1e9 < WARM_UP_SECONDS) {
            long runStart = System.nanoTime();
            new Renderer(plan, threads).render();
            lastWarmUp = (System.nanoTime() - runStart) / 1e9;
            warmUps++;
        }
        int n = (int) Math.min(MAX_RUNS, Math.max(runs, Math.ceil(MIN_TOTAL_SECONDS / Math.max(lastWarmUp, 1e-6))));
        return Timing.measure(n, () -> new Renderer(plan, threads).render());
    }

    private static String seconds(double s) {
        return String.format(java.util.Locale.ROOT, "%.2f s", s);
    }
}
