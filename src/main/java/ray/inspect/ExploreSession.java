package ray.inspect;

import com.google.gson.JsonArray;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import ray.Ray;
import ray.image.ImageDiff;
import ray.image.PngWriter;
import ray.render.RenderPlan;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.render.SamplePattern;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;

/**
 * One scene file as the explore page sees it: loaded, rendered exactly as {@code ray1 render}
 * renders it (the same renderer, plan and PNG encoding, so the page's pixels are the PNG's), its
 * reference and their difference, and the story of any pixel. {@link #reload()} reads the file
 * again, for a student editing the scene beside the page. Not thread-safe: the server calls it
 * from one thread.
 */
final class ExploreSession {
    private final Path sceneFile;
    private final Path referenceOverride;
    private Scene scene;
    private BufferedImage render;
    private byte[] renderPng;
    private String renderError;
    /** How the scene file is read (its course conventions, where data paths start), on every reload alike. */
    private final SceneOptions options;
    private long renderMillis;
    private int renderId;
    private final List<String> notes = new ArrayList<>();
    private Path referenceFile;
    private BufferedImage reference;
    private byte[] referencePng;
    private ImageDiff.Result difference;
    private byte[] differencePng;

    /**
     * @param referenceOverride the reference image to compare with, or null to look for
     *                          {@code reference/<name>.png} beside the scene or in its parent folder
     */
    ExploreSession(Path sceneFile, Path referenceOverride, SceneOptions options) {
        this.sceneFile = sceneFile;
        this.options = options;
        this.referenceOverride = referenceOverride;
    }

    /**
     * Loads the scene file and renders it. A scene that does not load throws its
     * {@link ray.scene.SceneException} and leaves the previous render in place; student code that
     * throws while rendering becomes the render's error (no image), as the page shows it.
     */
    void reload() {
        Scene loaded = SceneLoader.load(sceneFile, options);
        scene = loaded;
        renderId++;
        notes.clear();
        // The scene's warnings (FILE:LINE:COL: warning: …) first, where the page shows its notes.
        notes.addAll(loaded.warnings());
        render = null;
        renderPng = null;
        renderError = null;
        long start = System.nanoTime();
        try {
            // As ray1 render renders it: through the students' tree where they write it.
            RenderPlan plan = RenderPlan.of(loaded, 0, SamplePattern.GRID).withAcceleration(ray.accel.Acceleration.ofAssignment());
            RenderResult result = new Renderer(plan, 0).render();
            render = PngWriter.toBufferedImage(result.image, loaded.getExposure());
            renderPng = png(render);
        } catch (RuntimeException | StackOverflowError e) {
            renderError = "the render failed: " + Failure.oneLine(e);
        }
        renderMillis = (System.nanoTime() - start) / 1_000_000;
        cameraNote(loaded);
        compareWithReference(loaded);
    }

    /** The center pixel's camera ray, checked as {@code ray1 trace} checks it: a stub camera is named at once. */
    private void cameraNote(Scene loaded) {
        try {
            Ray ray = loaded.getCamera().generateRay(0.5, 0.5);
            String problem = CameraRayCheck.problem(loaded.getCamera(), ray);
            if (problem != null) {
                notes.add(problem);
            }
        } catch (RuntimeException | StackOverflowError e) {
            notes.add(loaded.getCamera().getClass().getSimpleName() + ".generateRay threw " + Failure.oneLine(e));
        }
    }

    private void compareWithReference(Scene loaded) {
        referenceFile = referenceOverride != null ? referenceOverride : findReference(sceneFile, SceneFiles.nameOf(sceneFile));
        reference = null;
        referencePng = null;
        difference = null;
        differencePng = null;
        if (referenceFile == null) {
            return;
        }
        try {
            byte[] bytes = Files.readAllBytes(referenceFile);
            reference = ImageIO.read(new java.io.ByteArrayInputStream(bytes));
            if (reference == null) {
                notes.add(referenceFile + " is not an image ray1 can read (expected a PNG)");
                referenceFile = null;
                return;
            }
            referencePng = bytes;
        } catch (IOException e) {
            notes.add("the reference " + referenceFile + " cannot be read: " + e.getMessage());
            referenceFile = null;
            return;
        }
        if (render != null) {
            difference = ImageDiff.compare(reference, render);
            if (difference.sameSize()) {
                differencePng = png(difference.heatMap());
            } else {
                notes.add("the reference is " + reference.getWidth() + "×" + reference.getHeight() + " but the scene renders "
                        + loaded.getWidth() + "×" + loaded.getHeight() + ": no difference to show");
            }
        }
    }

    /** {@code reference/<name>.png} in the scene's folder or the one above it (scenes/hard/x.xml → scenes/reference/x.png), or null. */
    static Path findReference(Path sceneFile, String name) {
        Path folder = sceneFile.toAbsolutePath().normalize().getParent();
        for (int up = 0; up < 2 && folder != null; up++, folder = folder.getParent()) {
            Path candidate = folder.resolve("reference").resolve(name + ".png");
            if (Files.isRegularFile(candidate)) {
                return candidate;
            }
        }
        return null;
    }

    /** What the page shows around the images: the scene, the render's state, the reference's comparison and the outline to draw. */
    JsonObject summary() {
        JsonObject s = new JsonObject();
        s.addProperty("scene", sceneFile.toString().replace('\\', '/'));
        s.addProperty("name", SceneFiles.nameOf(sceneFile));
        s.addProperty("width", scene.getWidth());
        s.addProperty("height", scene.getHeight());
        s.addProperty("renderId", renderId);
        s.addProperty("renderMillis", renderMillis);
        s.addProperty("renderError", renderError);
        JsonArray notesJson = new JsonArray();
        notes.forEach(notesJson::add);
        s.add("notes", notesJson);
        if (referenceFile == null) {
            s.add("reference", JsonNull.INSTANCE);
        } else {
            JsonObject r = new JsonObject();
            r.addProperty("file", ray.ShortPaths.of(referenceFile));
            r.addProperty("summary", difference == null ? "no render to compare" : difference.summary());
            r.addProperty("passed", difference != null && difference.passed());
            r.addProperty("sameSize", difference != null && difference.sameSize());
            s.add("reference", r);
        }
        SceneOutline.of(scene, s);
        return s;
    }

    /** The loaded scene's warnings, which the page shows among its notes. */
    List<String> warnings() {
        return scene.warnings();
    }

    /** The story of pixel (x, y), or null with {@code problem} when it lies outside the image. */
    JsonObject trace(int x, int y) {
        int[] value = render == null ? null : rgb(render, x, y);
        int[] ref = reference != null && x < reference.getWidth() && y < reference.getHeight() ? rgb(reference, x, y) : null;
        // Labelled as ray1 trace labels it, so the story's text is that command's output.
        return new PixelStory(scene, sceneFile.toString()).of(x, y, value, ref);
    }

    /** Why (x, y) is no pixel of the image, or null. */
    String outOfRange(int x, int y) {
        return PixelTrace.outOfRange(scene, sceneFile.toString(), x, y);
    }

    byte[] renderPng() {
        return renderPng;
    }

    String renderError() {
        return renderError;
    }

    byte[] referencePng() {
        return referencePng;
    }

    byte[] differencePng() {
        return differencePng;
    }

    private static int[] rgb(BufferedImage image, int x, int y) {
        int p = image.getRGB(x, y);
        return new int[] {p >> 16 & 255, p >> 8 & 255, p & 255};
    }

    private static byte[] png(BufferedImage image) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try {
            if (!ImageIO.write(image, "png", bytes)) {
                throw new IOException("no PNG writer is available");
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return bytes.toByteArray();
    }
}
