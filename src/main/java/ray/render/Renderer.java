package ray.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import ray.camera.Camera;
import ray.image.Image;
import ray.math.Vec3;
import ray.scene.Scene;

/**
 * The pixel loop. Pixel (i, j), j from the bottom, is sampled on an n×n grid, n = round(√N) for N
 * samples per pixel, at image point ((i + (a + ½)/n)/nx, (j + (b + ½)/n)/ny), and the samples are
 * averaged. Threads pull whole rows from a shared counter; every pixel is computed the same way
 * whichever thread takes it, so the image is identical for any thread count.
 */
public final class Renderer {
    private final Scene scene;
    private final int samplesPerPixel;
    private final int threads;

    /**
     * @param samplesPerPixel N, or 0 for the scene's own {@code <samples>}
     * @param threads         worker threads, or 0 for one per available core
     */
    public Renderer(Scene scene, int samplesPerPixel, int threads) {
        if (samplesPerPixel < 0 || threads < 0) {
            throw new IllegalArgumentException("samples and threads must be ≥ 0");
        }
        this.scene = scene;
        this.samplesPerPixel = samplesPerPixel > 0 ? samplesPerPixel : scene.getSamples();
        this.threads = threads > 0 ? threads : Runtime.getRuntime().availableProcessors();
    }

    /** n, the side of the per-pixel sample grid: round(√N), at least 1. */
    public static int gridSide(int samplesPerPixel) {
        return Math.max(1, (int) Math.round(Math.sqrt(samplesPerPixel)));
    }

    public RenderResult render() {
        long startNanos = System.nanoTime();
        int width = scene.getWidth();
        int height = scene.getHeight();
        Image image = new Image(width, height);
        AtomicInteger nextRow = new AtomicInteger();
        List<PixelTracer> tracers = new ArrayList<>();
        List<Thread> workers = new ArrayList<>();
        List<Throwable> failures = new ArrayList<>();
        int workerCount = Math.min(threads, height);
        for (int k = 0; k < workerCount; k++) {
            PixelTracer tracer = new PixelTracer(scene);
            tracers.add(tracer);
            Thread worker = new Thread(() -> {
                for (int j = nextRow.getAndIncrement(); j < height; j = nextRow.getAndIncrement()) {
                    renderRow(tracer, image, j);
                }
            }, "render-" + k);
            worker.setUncaughtExceptionHandler((t, e) -> {
                synchronized (failures) {
                    failures.add(e);
                }
                nextRow.set(height);
            });
            workers.add(worker);
        }
        if (workerCount == 1) {
            workers.get(0).run();
        } else {
            workers.forEach(Thread::start);
            for (Thread worker : workers) {
                try {
                    worker.join();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IllegalStateException("interrupted while rendering", e);
                }
            }
        }
        if (!failures.isEmpty()) {
            Throwable first = failures.get(0);
            throw first instanceof RuntimeException ? (RuntimeException) first : new IllegalStateException(first);
        }
        RayStats total = new RayStats();
        tracers.forEach(t -> total.add(t.stats()));
        int n = gridSide(samplesPerPixel);
        return new RenderResult(image, total, n * n, workerCount, (System.nanoTime() - startNanos) / 1e9);
    }

    private void renderRow(PixelTracer tracer, Image image, int j) {
        Camera camera = scene.getCamera();
        int width = scene.getWidth();
        int height = scene.getHeight();
        int n = gridSide(samplesPerPixel);
        double weight = 1.0 / (n * n);
        for (int i = 0; i < width; i++) {
            double r = 0, g = 0, b = 0;
            for (int a = 0; a < n; a++) {
                for (int c = 0; c < n; c++) {
                    double u = (i + (a + 0.5) / n) / width;
                    double v = (j + (c + 0.5) / n) / height;
                    Vec3 radiance = tracer.cameraRadiance(camera.generateRay(u, v));
                    r += radiance.x;
                    g += radiance.y;
                    b += radiance.z;
                }
            }
            image.set(i, j, new Vec3(r * weight, g * weight, b * weight));
        }
    }
}
