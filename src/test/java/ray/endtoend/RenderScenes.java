package ray.endtoend;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.assignment.Task;
import ray.assignment.TaskTable;
import ray.image.PngWriter;
import ray.render.PixelKinds;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.testing.ProjectFolder;

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
     * The task whose code each scene exercises most, as the table of tasks lists them under each
     * task's {@code scenes}: the render test of that task renders it. {@link SceneTasksTest} checks
     * that every scene under scenes/ is some task's, once, so a new scene cannot go ungraded.
     */
    static Map<String, Task> tasksOfScenes() {
        Map<String, Task> tasks = new LinkedHashMap<>();
        for (Task task : TaskTable.standard().all()) {
            for (String scene : task.scenes()) {
                tasks.putIfAbsent(scene, task);
            }
        }
        return Collections.unmodifiableMap(tasks);
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

    /** The parameters of a render test class: the names of its task's scenes, as one-element arrays. */
    static List<Object[]> scenesOf(Class<?> renderTest) {
        List<Object[]> list = new ArrayList<>();
        Task task = TaskTable.standard().ofTestClass(renderTest.getName()).orElseThrow(() -> new IllegalStateException(
                renderTest.getName() + " matches no task's tests in " + TaskTable.PROJECT_FILE));
        for (String name : task.scenes()) {
            list.add(new Object[] {name});
        }
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
