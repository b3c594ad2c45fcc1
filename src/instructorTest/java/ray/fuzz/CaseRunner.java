package ray.fuzz;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.render.PixelWindow;
import ray.render.RenderPlan;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.render.SamplePattern;
import ray.scene.Scene;
import ray.scene.SceneException;
import ray.scene.SceneLoader;

/**
 * Runs one case in a worker's copy of the corpus: writes the damaged file, loads the scene as
 * {@code ray1 render} does, renders a small window of it, and puts the original file back.
 *
 * <p>A clean error is a {@link SceneException} whose message is one line,
 * {@code FILE:LINE:COL: problem}, with FILE an existing file or the scene, LINE within it, and a
 * problem that says what was expected. A render is clean when it returns and tone-maps. Every
 * other end is a failure.
 */
final class CaseRunner {
    /** Side of the rendered window: enough pixels to reach every surface code path the centre of a scene uses. */
    static final int WINDOW = 4;
    /** Samples per pixel of the fuzz render, at most: a mutated {@code <samples>} is checked by loading, not paid for. */
    static final int MAX_SAMPLES = 16;

    private final Corpus corpus;
    private final Path folder;

    CaseRunner(Corpus corpus, Path folder) {
        this.corpus = corpus;
        this.folder = folder;
    }

    /** Runs the case with its damaged file, {@code damaged} (see {@link #damaged}). */
    Outcome run(FuzzCase c, byte[] damaged) {
        Path target = folder.resolve(c.target.toString());
        write(target, damaged);
        long start = System.nanoTime();
        try {
            return loadAndRender(folder.resolve(c.scene.toString()), start);
        } finally {
            write(target, corpus.original(c.target));
        }
    }

    /** The bytes the case writes in place of its target. */
    static byte[] damaged(Corpus corpus, FuzzCase c) {
        return c.damage(corpus.original(c.target));
    }

    private static Outcome loadAndRender(Path sceneFile, long start) {
        Scene scene;
        try {
            scene = SceneLoader.load(sceneFile);
        } catch (SceneException e) {
            String bad = ErrorFormat.problemWith(e, sceneFile);
            return bad == null ? Outcome.error(e.problem(), System.nanoTime() - start)
                    : Outcome.failed("badly formed error: " + bad + ": " + e.getMessage(), System.nanoTime() - start);
        } catch (Throwable t) {
            return Outcome.failed("loading threw " + describe(t), System.nanoTime() - start);
        }
        try {
            int w = Math.min(WINDOW, scene.getWidth());
            int h = Math.min(WINDOW, scene.getHeight());
            PixelWindow centre = new PixelWindow((scene.getWidth() - w) / 2, (scene.getHeight() - h) / 2, w, h);
            RenderPlan plan = RenderPlan.of(scene, Math.min(scene.getSamples(), MAX_SAMPLES), SamplePattern.GRID)
                    .withWindow(centre);
            RenderResult result = new Renderer(plan, 1).render();
            PngWriter.toBufferedImage(result.image, scene.getExposure());
            int nonFinite = 0;
            for (int j = 0; j < h; j++) {
                for (int i = 0; i < w; i++) {
                    Vec3 c = result.image.get(i, j);
                    nonFinite += Double.isFinite(c.x) && Double.isFinite(c.y) && Double.isFinite(c.z) ? 0 : 1;
                }
            }
            return Outcome.rendered(nonFinite, System.nanoTime() - start);
        } catch (Throwable t) {
            return Outcome.failed("rendering threw " + describe(t), System.nanoTime() - start);
        }
    }

    /** The exception and where in the framework it came from. */
    static String describe(Throwable t) {
        StringWriter trace = new StringWriter();
        t.printStackTrace(new PrintWriter(trace));
        String[] lines = trace.toString().split("\n");
        StringBuilder s = new StringBuilder(lines[0].strip());
        for (int i = 1, shown = 0; i < lines.length && shown < 4; i++) {
            if (lines[i].contains("ray.")) {
                s.append(" | ").append(lines[i].strip());
                shown++;
            }
        }
        return s.toString();
    }

    private static void write(Path file, byte[] bytes) {
        try {
            Files.write(file, bytes);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
