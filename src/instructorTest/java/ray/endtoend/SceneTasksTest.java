package ray.endtoend;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.Test;
import ray.scene.SceneFiles;

/**
 * Every shipped scene is graded exactly once: each scene under scenes/ has a task in
 * the table of tasks' {@code scenes} (so a new scene cannot be forgotten), every listed scene exists and
 * has a reference image, and no two scenes share a name (they would share a reference image).
 *
 * <p>An instructor's check, kept out of the handout: a student's own scenes (scenes/my-test.xml)
 * just render with {@code gradle run} and are never graded, so they need no task and no reference.
 */
public class SceneTasksTest {
    @Test
    public void everySceneUnderScenesHasATask() {
        List<String> unassigned = new ArrayList<>();
        List<Path> scenes = RenderScenes.sceneFiles();
        assertTrue("no scenes found under " + RenderScenes.folder(), !scenes.isEmpty());
        for (Path file : scenes) {
            if (!RenderScenes.tasksOfScenes().containsKey(SceneFiles.nameOf(file))) {
                unassigned.add(file.toString());
            }
        }
        assertTrue("scenes without a task; add each to a task's scenes in the table of tasks (and run gradle references): " + unassigned,
                unassigned.isEmpty());
    }

    @Test
    public void everyAssignedSceneExistsAndHasAReference() {
        List<String> problems = new ArrayList<>();
        for (String name : RenderScenes.tasksOfScenes().keySet()) {
            if (!Files.isRegularFile(RenderScenes.fileOf(name))) {
                problems.add("no scene file " + name + ".xml under " + RenderScenes.folder());
            } else if (!Files.isRegularFile(RenderScenes.referenceOf(name))) {
                problems.add("no reference " + RenderScenes.referenceOf(name) + " (run gradle references)");
            }
        }
        assertTrue(String.join("; ", problems), problems.isEmpty());
    }

    @Test
    public void noSceneIsTwoTasksScenes() {
        Map<String, String> owner = new HashMap<>();
        for (ray.assignment.Task task : ray.assignment.TaskTable.standard().all()) {
            for (String scene : task.scenes()) {
                String previous = owner.putIfAbsent(scene, task.id());
                assertEquals(scene + " is a scene of two tasks in the table of tasks", null, previous);
            }
        }
    }

    @Test
    public void noTwoScenesShareAName() {
        Map<String, Path> seen = new HashMap<>();
        for (Path file : RenderScenes.sceneFiles()) {
            Path previous = seen.putIfAbsent(SceneFiles.nameOf(file), file);
            assertEquals("two scenes named " + SceneFiles.nameOf(file) + " would share one reference image", null, previous);
        }
    }
}
