package ray.endtoend;

import java.util.EnumSet;
import java.util.Set;
import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.camera.PerspectiveCamera;
import ray.surface.SurfaceKind;
import ray.render.RenderPlan;
import ray.render.TaskProbes;
import ray.render.TaskProbes.Part;
import ray.scene.Scene;
import ray.shading.Effect;
import ray.surface.Surface;
import ray.testing.StudentTask;

/**
 * Which tasks a scene's render runs, and one plain check per task that any finished solution
 * passes (a ray straight at a sphere hits it, a group reports its one hit, ...), so that a render
 * test that fails can say whether its own task or another, unfinished one is to blame.
 *
 * <p>These checks never decide a grade: a render test passes or fails by its image alone, and the
 * checks only choose the words of a failure. Each expects what the task's contract promises and
 * nothing more (a ray's direction may have any length; hits are compared with a tolerance). The
 * cases are the framework's {@link TaskProbes}, which {@code ray1 render} also runs to say which
 * tasks are still stubs.
 */
final class BasicChecks {
    private BasicChecks() {
    }

    /** The tasks whose code renders {@code scene}: the camera and the group always, and each primitive or texture it holds. */
    static Set<StudentTask> tasksOf(Scene scene) {
        Set<StudentTask> tasks = EnumSet.of(StudentTask.CAMERA, StudentTask.GROUP);
        addTasksOf(scene.getSurfaces(), tasks);
        // Texture lookups, as the renderer's plan counts them: a lit shader with a texture on any
        // surface, named in the scene or written inline in the shader.
        if (RenderPlan.of(scene).runs(Effect.TEXTURES)) {
            tasks.add(StudentTask.TEXTURE);
        }
        return tasks;
    }

    private static void addTasksOf(Surface surface, Set<StudentTask> tasks) {
        // The primitive's task as the renderer's pixel kinds name it (a mesh's or box's parts are triangles).
        int number = SurfaceKind.of(surface).task;
        for (StudentTask task : StudentTask.values()) {
            if (task.number == number) {
                tasks.add(task);
            }
        }
        for (Surface child : surface.children()) {
            addTasksOf(child, tasks);
        }
    }

    /** What the task's code gets wrong in its plain check, or null when the check passes. */
    static String problem(StudentTask task, Scene scene) {
        switch (task) {
            case CAMERA:
                Part camera = cameraPart(scene.getCamera());
                return camera == null ? null : TaskProbes.probe(camera).problem;
            case SPHERE:
                return TaskProbes.probe(Part.SPHERE).problem;
            case TRIANGLE:
                return TaskProbes.probe(Part.TRIANGLE).problem;
            case GROUP:
                return TaskProbes.probe(Part.GROUP).problem;
            case TEXTURE:
                String repeat = TaskProbes.probe(Part.REPEAT_TEXTURE).problem;
                return repeat != null ? repeat : TaskProbes.probe(Part.CLAMP_TEXTURE).problem;
            case CYLINDER:
                return TaskProbes.probe(Part.CYLINDER).problem;
            default:
                return null;
        }
    }

    /** The scene's kind of camera: the one whose code renders it (a camera of the framework's own has no check). */
    private static Part cameraPart(Camera camera) {
        return camera instanceof OrthographicCamera ? Part.ORTHOGRAPHIC_CAMERA
                : camera instanceof PerspectiveCamera ? Part.PERSPECTIVE_CAMERA : null;
    }
}
