package ray.endtoend;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.accel.Acceleration;
import ray.assignment.Task;
import ray.assignment.TaskTable;
import ray.image.PngWriter;
import ray.render.PixelKinds;
import ray.render.RenderPlan;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;
import ray.shading.Course;
import ray.testing.ProjectFolder;

/**
 * The shipped scenes (every *.xml under scenes/, and under scenes-2019/ for the tasks of the course's
 * 2019 conventions, except the reference folders), the task each one's graded render test counts
 * toward, and full-size renders of them. A scene renders by the conventions of its folder: scenes/
 * by 2017's, scenes-2019/ by 2019's, whatever the assignment's course.
 */
final class RenderScenes {
    /**
     * The project's scenes/ folder, absolute, wherever the tests run from ({@link ProjectFolder}). A
     * method, not a constant: a project folder that cannot be found then fails the test that asks,
     * with its one-line reason, rather than this class's initialization.
     */
    static Path folder() {
        return ProjectFolder.resolve(SceneOptions.SCENES_2017);
    }

    /** The folder of the scenes of {@code course}'s conventions: scenes/ for 2017, scenes-2019/ for 2019. */
    static Path folder(Course course) {
        return ProjectFolder.resolve(course == Course.Y2019 ? SceneOptions.SCENES_2019 : SceneOptions.SCENES_2017);
    }

    /** The course whose conventions a scene file under {@link #folder(Course)} renders by: its folder's. */
    static Course courseOf(Path sceneFile) {
        Course course = SceneOptions.courseOfFolder(sceneFile);
        return course != null ? course : Course.Y2017;
    }

    /** A scene file loaded by the conventions of its folder ({@link #courseOf}), its data beside it. */
    static Scene load(Path sceneFile) {
        return SceneLoader.load(sceneFile, SceneOptions.of(courseOf(sceneFile), null));
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

    /** Every scene file under {@code course}'s folder, sorted, except any under its reference folder. */
    static List<Path> sceneFiles(Course course) {
        Path folder = folder(course);
        return java.nio.file.Files.isDirectory(folder) ? SceneFiles.under(folder, folder.resolve("reference")) : List.of();
    }

    /**
     * The scene file called {@code name}.xml anywhere under scenes/ or another course's folder, or
     * scenes/NAME.xml when there is none (to be reported missing).
     */
    static Path fileOf(String name) {
        for (Course course : Course.values()) {
            for (Path p : sceneFiles(course)) {
                if (SceneFiles.nameOf(p).equals(name)) {
                    return p;
                }
            }
        }
        return folder().resolve(name + ".xml");
    }

    /** The reference image of the scene {@code name}: in the reference folder of its course's folder. */
    static Path referenceOf(String name) {
        return folder(courseOf(fileOf(name))).resolve("reference").resolve(name + ".png");
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
        return PngWriter.toBufferedImage(new Renderer(plan(scene, Acceleration.ofAssignment()), 0).render().image, scene.getExposure());
    }

    /** A render test's plan: the scene's own, its boxes and meshes searched as {@code acceleration} says. */
    private static RenderPlan plan(Scene scene, Acceleration acceleration) {
        return RenderPlan.of(scene).withAcceleration(acceleration);
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
        return renderWithKinds(scene, Acceleration.ofAssignment());
    }

    /** As {@link #renderWithKinds(Scene)}, its boxes and meshes searched as {@code acceleration} says. */
    static Rendered renderWithKinds(Scene scene, Acceleration acceleration) {
        RenderResult result = new Renderer(plan(scene, acceleration), 0).renderWithKinds();
        return new Rendered(PngWriter.toBufferedImage(result.image, scene.getExposure()), result.kinds);
    }
}
