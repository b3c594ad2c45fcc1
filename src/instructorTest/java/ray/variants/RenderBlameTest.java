package ray.variants;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.SolutionMarkers;

/**
 * A render test names the task whose code is wrong. With a finished Task 1 and the handout's stubs
 * of Tasks 2–4, every camera render fails (it needs spheres, triangles and the group), and each
 * failure says which tasks are unfinished instead of sending the student back to Task 1; a
 * sphere that throws makes the camera renders blame Task 2's file, not Task 1's. A wrong camera
 * with every other task finished is still Task 1's fault, with its basic check's numbers.
 */
public class RenderBlameTest {
    private static final String CAMERA_RENDERS = "ray.endtoend.CameraRenderTest";

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void unfinishedOtherTasksAreNamedInsteadOfTheCamera() throws Exception {
        Path files = folder.newFolder("stubs").toPath();
        for (String name : List.of("Sphere", "Triangle", "Group")) {
            write(files, name, SolutionMarkers.studentVersion(solution(name), name + ".java"));
        }
        List<VariantGrading.Outcome> outcomes = cameraRenders(Variant.written("stubs of Tasks 2-4", 1, files));
        for (VariantGrading.Outcome o : outcomes) {
            assertFalse(o + " passed with the stubs of Tasks 2-4", o.passed());
            assertTrue(o.failure, o.failure.contains("ray.testing.NotThisTasksFault"));
            assertTrue(o.failure, o.failure.contains("which do not work yet"));
            assertTrue(o.failure, o.failure.contains("Task 4 (Group): Group.intersect finds no hit"));
            assertFalse(o.failure, o.failure.contains("Work on the TODO(Task 1)"));
        }
    }

    @Test
    public void aSphereThatThrowsIsBlamedOnTask2() throws Exception {
        Path files = folder.newFolder("throwing").toPath();
        String stub = SolutionMarkers.studentVersion(solution("Sphere"), "Sphere.java");
        String throwing = stub.replaceFirst("return false;", "throw new IllegalStateException(\"unfinished\");");
        assertFalse("the sphere stub has no 'return false;' to replace", throwing.equals(stub));
        write(files, "Sphere", throwing);
        List<VariantGrading.Outcome> outcomes = cameraRenders(Variant.written("throwing sphere", 1, files));
        List<String> blamed = outcomes.stream().filter(o -> !o.passed()).map(o -> o.failure).collect(Collectors.toList());
        assertFalse("no camera render met the throwing sphere", blamed.isEmpty());
        for (String failure : blamed) {
            // Labelled with the task whose file threw, in the words of that task's own unit tests.
            assertTrue(failure, failure.contains("[Task 2 (Sphere)] your code threw java.lang.IllegalStateException: unfinished at Sphere.java:"));
            assertTrue(failure, failure.contains("Work on the TODO(Task 2) comments in src/main/java/ray/surface/Sphere.java"));
            assertFalse(failure, failure.contains("Work on the TODO(Task 1)"));
        }
    }

    @Test
    public void aWrongCameraIsStillTask1sFaultWithItsNumbers() throws Exception {
        List<VariantGrading.Outcome> outcomes = cameraRenders(Variant.wrong("camera-flipped-v", 1));
        assertEquals(outcomes.toString(), 0, outcomes.stream().filter(VariantGrading.Outcome::passed).count());
        for (VariantGrading.Outcome o : outcomes) {
            assertFalse(o.failure, o.failure.contains("NotThisTasksFault"));
            assertTrue(o.failure, o.failure.contains("code fails a basic check: "));
            assertTrue(o.failure, o.failure.contains("Work on the TODO(Task 1)"));
        }
    }

    private List<VariantGrading.Outcome> cameraRenders(Variant variant) throws Exception {
        List<VariantGrading.Outcome> outcomes = VariantGrading.run(variant, (task, type) -> type.equals(CAMERA_RENDERS),
                folder.newFolder().toPath());
        assertFalse(variant + " ran no camera render test", outcomes.isEmpty());
        return outcomes;
    }

    private static String solution(String surface) throws IOException {
        return Files.readString(Path.of("src/main/java/ray/surface", surface + ".java"));
    }

    private static void write(Path root, String surface, String source) throws IOException {
        Path file = root.resolve("ray/surface/" + surface + ".java");
        Files.createDirectories(file.getParent());
        Files.writeString(file, source);
    }
}
