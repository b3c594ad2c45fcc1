package ray.endtoend;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.image.PngWriter;
import ray.render.PixelKinds;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.testing.ProjectFolder;
import ray.testing.StudentTask;

/**
 * The shipped scenes (every *.xml under scenes/, except the reference folder), the task each one's
 * graded render test counts toward, and full-size renders of them.
 */
final class RenderScenes {
    /**
     * The project's scenes/ folder, absolute, wherever the tests run from ({@link ProjectFolder}). A
     * method, not a constant: a project folder that cannot be found then fails the test that asks,
     * with its one-line reason, rather than this class's initialization.
     */
    static Path folder() {
        return ProjectFolder.resolve("scenes");
    }

    /** The reference renders, made by the instructor's solution ({@code gradle references}). */
    static Path referenceFolder() {
        return folder().resolve("reference");
    }

    /**
     * The task whose code each scene exercises most. Every scene under scenes/ must be listed here
     * exactly once ({@link SceneTasksTest} fails otherwise), so a new scene cannot go ungraded.
     */
    static final Map<String, StudentTask> TASKS;

    static {
        Map<String, StudentTask> tasks = new LinkedHashMap<>();
        // Task 1: an orthographic view, and 16 samples per pixel at arbitrary image points.
        tasks.put("wire-box-ortho", StudentTask.CAMERA);
        tasks.put("antialiased", StudentTask.CAMERA);
        // Task 2: spheres alone.
        tasks.put("one-sphere", StudentTask.SPHERE);
        tasks.put("one-sphere-phong", StudentTask.SPHERE);
        // Task 3: meshes and boxes (boxes are 12 triangles each), flat and interpolated normals.
        tasks.put("mesh-flat", StudentTask.TRIANGLE);
        tasks.put("mesh-smooth", StudentTask.TRIANGLE);
        tasks.put("two-boxes", StudentTask.TRIANGLE);
        tasks.put("rgb-normals", StudentTask.TRIANGLE);
        // A box given upside down (minPt.y above maxPt.y), built as given: its top's normal points down.
        tasks.put("inverted-box", StudentTask.TRIANGLE);
        // Task 4: overlapping surfaces, nested transformed groups, reflection rays.
        tasks.put("wire-box", StudentTask.GROUP);
        tasks.put("group-transforms", StudentTask.GROUP);
        tasks.put("glazed-sphere", StudentTask.GROUP);
        // Textured scenes (scenes/textured), each under the task whose mistakes it shows most plainly:
        // the globe's marks show the sphere's (u, v), the tablecloth the triangles' blended vt, and
        // the eclipse and the diagnostic chart the repeat and clamp lookups.
        tasks.put("globe", StudentTask.SPHERE);
        tasks.put("tablecloth", StudentTask.TRIANGLE);
        tasks.put("eclipse", StudentTask.TEXTURE);
        tasks.put("diagnostic", StudentTask.TEXTURE);
        // Task 6 (extra credit): capped cylinders, upright and placed by a group.
        tasks.put("cylinder", StudentTask.CYLINDER);
        // The numerically hard cases (scenes/hard, docs/numerics.md), each under the task whose code it strains most.
        tasks.put("far-tiny-sphere", StudentTask.SPHERE);
        tasks.put("huge-ground-sphere", StudentTask.SPHERE);
        tasks.put("inside-closed-mesh", StudentTask.TRIANGLE);
        tasks.put("far-from-origin", StudentTask.GROUP);
        TASKS = Collections.unmodifiableMap(tasks);
    }

    private RenderScenes() {
    }

    /** Every scene file under scenes/, sorted, except any under scenes/reference. */
    static List<Path> sceneFiles() {
        return SceneFiles.under(folder(), referenceFolder());
    }

    /** The scene file called {@code name}.xml anywhere under scenes/, or scenes/NAME.xml when there is none (to be reported missing). */
    static Path fileOf(String name) {
        for (Path p : sceneFiles()) {
            if (SceneFiles.nameOf(p).equals(name)) {
                return p;
            }
        }
        return folder().resolve(name + ".xml");
    }

    static Path referenceOf(String name) {
        return referenceFolder().resolve(name + ".png");
    }

    /**
     * A file as messages name it: relative to the project folder (scenes/hard/x.xml), as the student
     * types it and as the grader reads it back from a failure message, whatever the working folder;
     * a path outside the project (or already relative) as it is.
     */
    static Path shown(Path file) {
        Path project = ProjectFolder.get();
        return file.isAbsolute() && file.normalize().startsWith(project) ? project.relativize(file.normalize()) : file;
    }

    /** The parameters of a task's render test: the names of its scenes, as one-element arrays. */
    static List<Object[]> scenesOf(StudentTask task) {
        List<Object[]> list = new ArrayList<>();
        TASKS.forEach((name, t) -> {
            if (t == task) {
                list.add(new Object[] {name});
            }
        });
        return list;
    }

    /** A loaded scene rendered at its full size, as 8-bit pixels (PNG row order). */
    static BufferedImage render(Scene scene) {
        return PngWriter.toBufferedImage(new Renderer(scene, 0, 0).render().image, scene.getExposure());
    }

    /** A render as 8-bit pixels (PNG row order) and what each pixel shows in it. */
    record Rendered(BufferedImage image, PixelKinds kinds) {
    }

    /**
     * A loaded scene rendered at its full size as {@link #render} renders it (the same pixels), with
     * the kind of surface each pixel's camera rays hit first ({@link Renderer#renderWithKinds()}),
     * for saying what the pixels that differ show.
     */
    static Rendered renderWithKinds(Scene scene) {
        RenderResult result = new Renderer(scene, 0, 0).renderWithKinds();
        return new Rendered(PngWriter.toBufferedImage(result.image, scene.getExposure()), result.kinds);
    }
}
