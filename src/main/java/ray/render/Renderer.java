package ray.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import ray.AnswerRounds;
import ray.camera.Camera;
import ray.image.Image;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.surface.SurfaceKind;

/**
 * The pixel loop. Pixel (i, j), j from the bottom, is sampled on an n×n grid, n = round(√N) for N
 * samples per pixel, at image point ((i + (a + ½)/n)/nx, (j + (b + ½)/n)/ny) (or, with a jittered
 * {@link SamplePattern}, at a random point of each grid cell), and the samples are averaged.
 * Threads pull whole rows from a shared counter; every pixel is computed the same way whichever
 * thread takes it, so the image is identical for any thread count.
 *
 * <p>It runs a {@link RenderPlan}: the grid side and the primitive count come from the plan, and
 * effects the scene does not call for cost nothing, since nothing in the loop asks for them (no
 * lights means shaders loop over none, no Glazed shader means no reflection ray, one sample means
 * one camera ray per pixel).
 */
public final class Renderer {
    private final RenderPlan plan;
    private final Scene scene;
    private final int threads;
    /** Rows finished so far, for {@link #progress()}: one atomic increment per row, read by whoever shows progress. */
    private final AtomicInteger rowsDone = new AtomicInteger();
    /**
     * Render threads, kept between renders (a batch renders many scenes): a fresh thread starts
     * with small allocation buffers (TLABs) that the JVM grows only as it learns the thread's
     * rate, which measurably slowed short renders on two threads. Daemon threads, so an idle
     * pool never keeps the JVM alive.
     */
    private static final ExecutorService WORKERS = Executors.newCachedThreadPool(runnable -> {
        Thread thread = new Thread(runnable, "render-worker");
        thread.setDaemon(true);
        return thread;
    });

    /**
     * @param samplesPerPixel N, or 0 for the scene's own {@code <samples>}
     * @param threads         worker threads, or 0 for one per available core
     */
    public Renderer(Scene scene, int samplesPerPixel, int threads) {
        this(checkedPlan(scene, samplesPerPixel), threads);
    }

    /** @param threads worker threads, or 0 for one per available core */
    public Renderer(RenderPlan plan, int threads) {
        if (threads < 0) {
            throw new IllegalArgumentException("threads must be ≥ 0 (0 for one per core), got " + threads);
        }
        this.plan = plan;
        this.scene = plan.scene();
        this.threads = threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    private static RenderPlan checkedPlan(Scene scene, int samplesPerPixel) {
        if (samplesPerPixel < 0) {
            throw new IllegalArgumentException("samples must be ≥ 0 (0 for the scene's own), got " + samplesPerPixel);
        }
        return RenderPlan.of(scene, samplesPerPixel);
    }

    public RenderPlan plan() {
        return plan;
    }

    /** The share of rows finished, 0 to 1; safe to call from another thread while {@link #render()} runs. */
    public double progress() {
        return (double) rowsDone.get() / plan.window().height;
    }

    /** n, the side of the per-pixel sample grid: round(√N), at least 1. */
    public static int gridSide(int samplesPerPixel) {
        return Math.max(1, (int) Math.round(Math.sqrt(samplesPerPixel)));
    }

    /** Renders the plan's image; the result has no {@link RenderResult#kinds}. */
    public RenderResult render() {
        return render(false);
    }

    /**
     * Renders the plan's image, the same bits as {@link #render()}, and notes what each pixel's camera
     * rays hit first ({@link RenderResult#kinds}): the primitive kind of the closest hit the scene's
     * own search reported, as the shaders received it, so no ray is traced twice. Costs a byte per
     * pixel and a few stores per camera ray; a plain {@link #render()} does none of it.
     */
    public RenderResult renderWithKinds() {
        return render(true);
    }

    private RenderResult render(boolean recordKinds) {
        long startNanos = System.nanoTime();
        // The image is the plan's window (the whole image unless a study asks for part of it).
        int width = plan.window().width;
        int height = plan.window().height;
        Image image = new Image(width, height);
        PixelKinds kinds = recordKinds ? new PixelKinds(width, height) : null;
        int workerCount = Math.min(threads, height);
        List<CountingShading> shadings = new ArrayList<>();
        for (int k = 0; k < workerCount; k++) {
            shadings.add(new CountingShading(plan, recordKinds));
        }
        if (AnswerRounds.active()) {
            renderInRounds(shadings, image, kinds);
        } else {
            AtomicInteger nextRow = new AtomicInteger();
            runWorkers(workerCount, k -> {
                // A pixel's samples' votes, per kind: one array per worker, only when recording.
                int[] votes = recordKinds ? new int[SurfaceKind.count()] : null;
                for (int j = nextRow.getAndIncrement(); j < height; j = nextRow.getAndIncrement()) {
                    renderRow(shadings.get(k), image, j, kinds, votes, null, null);
                    rowsDone.incrementAndGet();
                }
            }, () -> nextRow.set(height));
        }
        RayStats total = new RayStats();
        shadings.forEach(t -> total.add(t.stats()));
        int n = plan.gridSide();
        return new RenderResult(image, kinds, plan, total, n * n, workerCount, (System.nanoTime() - startNanos) / 1e9);
    }

    /**
     * The render when answers may come late ({@link AnswerRounds}: while grading): each pixel is a
     * computation, rendered again in the next round until it used no guessed answer. Each worker keeps
     * its rows and its shading (the same copies of the scene's surfaces) from round to round, so that a
     * pixel asks the same questions of the same objects each time. The rows are in two halves, whose
     * rounds alternate: while the answers to one half's questions are being made, the other half renders.
     */
    private void renderInRounds(List<CountingShading> shadings, Image image, PixelKinds kinds) {
        int workerCount = shadings.size();
        int height = image.height();
        boolean[] pending = new boolean[image.width() * height];
        java.util.Arrays.fill(pending, true);
        // Each pending pixel's state: what it asked and was told in the rounds so far.
        Object[] states = new Object[pending.length];
        Object[] asked = new Object[2];
        boolean[] done = new boolean[2];
        try {
            for (int round = 1; !done[0] || !done[1]; round++) {
                for (int half = 0; half < 2; half++) {
                    if (done[half]) {
                        continue;
                    }
                    AnswerRounds.await(asked[half]);
                    int rowsOf = half;
                    AtomicInteger left = new AtomicInteger();
                    runWorkers(workerCount, k -> {
                        int[] votes = kinds != null ? new int[SurfaceKind.count()] : null;
                        // Worker k renders rows k, k + n, k + 2n, ...: those of this half.
                        for (int j = k; j < height; j += workerCount) {
                            if ((j / workerCount) % 2 == rowsOf) {
                                left.addAndGet(renderRow(shadings.get(k), image, j, kinds, votes, pending, states));
                            }
                        }
                    }, () -> { });
                    if (left.get() == 0) {
                        done[half] = true;
                        asked[half] = null;
                        continue;
                    }
                    asked[half] = AnswerRounds.ask();
                    if (asked[half] == null || round >= AnswerRounds.MAX_ROUNDS) {
                        throw new IllegalStateException("the render's answers never settled after " + round + " rounds");
                    }
                }
            }
            rowsDone.set(height);
        } finally {
            AnswerRounds.forget();
        }
    }

    /**
     * Runs {@code work(k)} for k = 0 … n − 1, k = 0 on the calling thread and the others on the pool,
     * and rethrows the first failure; {@code stopOthers} runs when one fails, so that the rest stop
     * after their current row.
     */
    private static void runWorkers(int n, java.util.function.IntConsumer work, Runnable stopOthers) {
        List<Runnable> workers = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            int index = k;
            workers.add(() -> {
                try {
                    work.accept(index);
                } catch (RuntimeException | Error e) {
                    stopOthers.run();
                    throw e;
                }
            });
        }
        // The calling thread is one of the workers; the others come from the pool.
        List<Future<?>> others = new ArrayList<>();
        for (Runnable worker : workers.subList(1, n)) {
            others.add(WORKERS.submit(worker));
        }
        Throwable failure = null;
        try {
            workers.get(0).run();
        } catch (RuntimeException | Error e) {
            failure = e;
        }
        for (Future<?> other : others) {
            try {
                other.get();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while rendering", e);
            } catch (ExecutionException e) {
                failure = failure != null ? failure : e.getCause();
            }
        }
        if (failure instanceof Error) {
            throw (Error) failure;
        }
        if (failure != null) {
            throw failure instanceof RuntimeException ? (RuntimeException) failure : new IllegalStateException(failure);
        }
    }

    /**
     * Row {@code row} of the window, counted from its bottom, into the image of the window, and when
     * {@code kinds} is not null into it too, each pixel by the kind most of its samples hit. With
     * {@code pending} (answers may come late), only the pixels still pending, each as a computation
     * of {@link AnswerRounds}: one that used a guess stays pending (and what it threw is dropped, since
     * a guess may have caused it). Returns how many pixels of the row are still pending.
     */
    private int renderRow(CountingShading shading, Image image, int row, PixelKinds kinds, int[] votes, boolean[] pending,
            Object[] states) {
        int width = plan.window().width;
        int stillPending = 0;
        for (int x = 0; x < width; x++) {
            if (pending == null) {
                image.set(x, row, pixel(shading, x, row, votes));
                if (kinds != null) {
                    kinds.set(x, row, SurfaceKind.mostVoted(votes));
                }
                continue;
            }
            int at = row * width + x;
            if (!pending[at]) {
                continue;
            }
            Vec3 color;
            AnswerRounds.begin(states[at]);
            try {
                if (votes != null) {
                    java.util.Arrays.fill(votes, 0);
                }
                color = pixel(shading, x, row, votes);
            } catch (RuntimeException | Error e) {
                Object state = AnswerRounds.end();
                if (state == null) {
                    throw e;
                }
                states[at] = state;
                stillPending++;
                continue;
            }
            Object state = AnswerRounds.end();
            if (state != null) {
                states[at] = state;
                stillPending++;
                continue;
            }
            image.set(x, row, color);
            if (kinds != null) {
                kinds.set(x, row, SurfaceKind.mostVoted(votes));
            }
            pending[at] = false;
            states[at] = null;
        }
        return stillPending;
    }

    /** The color of pixel {@code x} of row {@code row} of the window: its samples averaged, each sample's kind voted into {@code votes}. */
    private Vec3 pixel(CountingShading shading, int x, int row, int[] votes) {
        Camera camera = scene.getCamera();
        int width = scene.getWidth();
        int height = scene.getHeight();
        PixelWindow window = plan.window();
        int i = window.x + x;
        int j = window.firstRowFromBottom(height) + row;
        int n = plan.gridSide();
        SamplePattern pattern = plan.pattern();
        double weight = 1.0 / (n * n);
        double r = 0, g = 0, b = 0;
        for (int a = 0; a < n; a++) {
            for (int c = 0; c < n; c++) {
                double u = (i + pattern.x(i, j, a, c, n)) / width;
                double v = (j + pattern.y(i, j, a, c, n)) / height;
                Vec3 radiance = shading.cameraRadiance(camera.generateRay(u, v));
                if (votes != null) {
                    votes[shading.cameraKind().ordinal()]++;
                }
                r += radiance.x;
                g += radiance.y;
                b += radiance.z;
            }
        }
        return new Vec3(r * weight, g * weight, b * weight);
    }
}
