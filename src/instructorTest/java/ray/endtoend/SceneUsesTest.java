package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.Test;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.testing.StudentTask;

/**
 * The tasks a render's message says its scene uses come from what the scene holds: its camera and
 * group always, each primitive's task, and Task 5 when any surface's shader is textured, whether the
 * texture is named in the scene or written inline in the shader (eclipse's are inline). The test
 * summary lists a differing render under a task of these whose unit tests fail, so a task left out
 * here sent a render to "Renders" while its own task was failing.
 */
public class SceneUsesTest {
    @Test
    public void inlineTexturesCountAsTask5() throws Exception {
        Scene eclipse = SceneLoader.load(RenderScenes.fileOf("eclipse"));
        assertTrue(eclipse.getTextures().isEmpty()); // the point of this case: no named texture
        assertEquals(Set.of(StudentTask.of("camera-rays"), StudentTask.of("sphere"), StudentTask.of("group"), StudentTask.of("textures")), BasicChecks.tasksOf(eclipse));
        assertEquals("The scene uses Task 1 (Camera rays), Task 2 (Sphere), Task 4 (Group) and Task 5 (Textures).",
                RenderTestBase.usesLine(eclipse));
    }

    @Test
    public void anUntexturedSceneDoesNotUseTask5() throws Exception {
        assertEquals(Set.of(StudentTask.of("camera-rays"), StudentTask.of("sphere"), StudentTask.of("group")),
                BasicChecks.tasksOf(SceneLoader.load(RenderScenes.fileOf("one-sphere"))));
    }

    /**
     * A box or mesh big enough for a tree uses the bvh task where students write the tree, since every
     * render test then searches through theirs (a small box's 12 triangles are enough); where they do
     * not, the framework's tree is never to blame.
     */
    @Test
    public void meshesUseTheTreeTaskOnlyWhereItIsChosen() throws Exception {
        ray.assignment.Assignment before = ray.assignment.Assignment.current();
        try {
            ray.assignment.Assignment.use(ray.assignment.Assignment.preset("course-2019-part2"));
            assertEquals(Set.of(StudentTask.of("bvh")), BasicChecks.tasksOf(RenderScenes.load(RenderScenes.fileOf("two-boxes"))));
            assertEquals(Set.of(), BasicChecks.tasksOf(RenderScenes.load(RenderScenes.fileOf("one-sphere"))));
            ray.assignment.Assignment.use(ray.assignment.Assignment.preset("course-2017"));
            assertEquals(Set.of(StudentTask.of("camera-rays"), StudentTask.of("ray-color"), StudentTask.of("group"), StudentTask.of("triangle"),
                    StudentTask.of("lighting")), BasicChecks.tasksOf(RenderScenes.load(RenderScenes.fileOf("two-boxes"))));
        } finally {
            ray.assignment.Assignment.use(before);
        }
    }

    /**
     * Every graded render's own task is among those its scene uses, under the course preset that
     * chooses the task (course-2017, course-2019 and course-2019-part2 together choose every task).
     */
    @Test
    public void everyRendersOwnTaskIsAmongItsScenesTasks() throws Exception {
        ray.assignment.Assignment before = ray.assignment.Assignment.current();
        try {
            for (String preset : List.of("course-2017", "course-2019", "course-2019-part2")) {
                ray.assignment.Assignment.use(ray.assignment.Assignment.preset(preset));
                for (Map.Entry<String, ray.assignment.Task> e : RenderScenes.tasksOfScenes().entrySet()) {
                    if (ray.assignment.Assignment.current().number(e.getValue().id()) == 0) {
                        continue;
                    }
                    Set<StudentTask> uses = BasicChecks.tasksOf(RenderScenes.load(RenderScenes.fileOf(e.getKey())));
                    assertTrue(preset + ": " + e.getKey() + " uses " + uses, uses.contains(StudentTask.of(e.getValue().id())));
                }
            }
        } finally {
            ray.assignment.Assignment.use(before);
        }
    }
}
