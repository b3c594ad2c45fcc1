package ray.endtoend;

import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.Set;
import ray.accel.Acceleration;
import ray.camera.Camera;
import ray.camera.OrthographicCamera;
import ray.camera.PerspectiveCamera;
import ray.render.RenderPlan;
import ray.render.TaskProbes;
import ray.render.TaskProbes.Part;
import ray.scene.Scene;
import ray.shading.BrdfShader;
import ray.shading.Effect;
import ray.shading.LambertianBrdf;
import ray.shading.MicrofacetBrdf;
import ray.shading.PhongBrdf;
import ray.shading.Shader;
import ray.surface.Surface;
import ray.surface.SurfaceKind;
import ray.surface.TriangleSet;
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

    /**
     * The tasks of this assignment whose code renders {@code scene}, in their order: the camera, the
     * ray's color and the group always, each primitive or texture it holds, the students' tree when a
     * box or mesh is big enough for one, and the light loops when it is lit (a task the assignment does
     * not choose ships solved, and is never to blame).
     */
    static Set<StudentTask> tasksOf(Scene scene) {
        Set<String> ids = new HashSet<>(Set.of("camera-rays", "ray-color", "group"));
        addTasksOf(scene.getSurfaces(), ids);
        // Texture lookups, as the renderer's plan counts them: a lit shader with a texture on any
        // surface, named in the scene or written inline in the shader.
        RenderPlan plan = RenderPlan.of(scene);
        if (plan.runs(Effect.TEXTURES)) {
            ids.add("textures");
        }
        // The light loops of the Lambertian and Phong shaders (2017), or the reflection shader's loop
        // and the BRDFs it evaluates (2019: the Lambertian's and Phong's, or the microfacet ones), which
        // run when the scene has a light.
        if (plan.runs(Effect.LIGHTING)) {
            Set<Class<?>> brdfs = new HashSet<>();
            addBrdfsOf(scene.getSurfaces(), brdfs);
            if (brdfs.isEmpty()) {
                ids.add("lighting");
            } else {
                ids.add("reflection");
            }
            if (brdfs.contains(LambertianBrdf.class) || brdfs.contains(PhongBrdf.class)) {
                ids.add("brdfs");
            }
            if (brdfs.contains(MicrofacetBrdf.class)) {
                ids.add("microfacet");
            }
        }
        Set<StudentTask> tasks = new LinkedHashSet<>();
        for (StudentTask task : StudentTask.values()) {
            if (ids.contains(task.id)) {
                tasks.add(task);
            }
        }
        return tasks;
    }

    /** The classes of the BRDFs that the 2019 shaders of {@code surface} and its parts evaluate (none under 2017). */
    private static void addBrdfsOf(Surface surface, Set<Class<?>> brdfs) {
        addBrdfsOf(surface.getShader(), brdfs);
        for (Surface child : surface.children()) {
            addBrdfsOf(child, brdfs);
        }
    }

    /** A shader's BRDF, and those of the shaders it shades with (a glaze's substrate). */
    private static void addBrdfsOf(Shader shader, Set<Class<?>> brdfs) {
        if (shader instanceof BrdfShader) {
            brdfs.add(((BrdfShader) shader).brdf().getClass());
        }
        if (shader != null) {
            for (Shader part : shader.parts()) {
                addBrdfsOf(part, brdfs);
            }
        }
    }

    private static void addTasksOf(Surface surface, Set<String> ids) {
        // The primitive's task as the renderer's pixel kinds name it (a mesh's or box's parts are triangles).
        String id = SurfaceKind.of(surface).taskId;
        if (id != null) {
            ids.add(id);
        }
        // A box or mesh big enough for a tree is searched through the students' tree when they write it.
        if (surface instanceof TriangleSet && ((TriangleSet) surface).hasTree()) {
            ids.add(Acceleration.STUDENTS_TREE_TASK);
        }
        for (Surface child : surface.children()) {
            addTasksOf(child, ids);
        }
    }

    /**
     * What the task's code gets wrong in its plain check, or null when the check passes: the probes
     * of its classes in the table's order, of a camera class only when it is the scene's camera.
     */
    static String problem(StudentTask task, Scene scene) {
        Part sceneCamera = cameraPart(scene.getCamera());
        for (Part part : Part.values()) {
            boolean camera = part == Part.PERSPECTIVE_CAMERA || part == Part.ORTHOGRAPHIC_CAMERA;
            if (part.taskId.equals(task.id) && (!camera || part == sceneCamera)) {
                String problem = TaskProbes.probe(part).problem;
                if (problem != null) {
                    return problem;
                }
            }
        }
        return null;
    }

    /** The scene's kind of camera: the one whose code renders it (a camera of the framework's own has no check). */
    private static Part cameraPart(Camera camera) {
        return camera instanceof OrthographicCamera ? Part.ORTHOGRAPHIC_CAMERA
                : camera instanceof PerspectiveCamera ? Part.PERSPECTIVE_CAMERA : null;
    }
}
