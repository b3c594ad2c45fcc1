package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.google.gson.Gson;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The PrairieLearn folder works as PrairieLearn uses it: its run script, given a folder laid out
 * like /grade (student/ holds the student's files; GRADE_ROOT names it), grades them into
 * results/results.json in PrairieLearn's format with java alone, finding the grading tree and lib/
 * beside itself as in the image. The submission is the solution with a stubbed sphere and without
 * the optional cylinder: Task 2's tests score nothing, every other task's full, so the score is below 1.
 */
public class PrairieLearnBundleTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void runGradesTheStudentFilesIntoPrairieLearnsResultsJson() throws Exception {
        Path folder = FOLDER.getRoot().toPath().resolve("prairielearn");
        KitInputs kit = new KitInputs();
        PrairieLearnBundle.build(Path.of("."), folder, "example/ray1-grader:test", kit.classes, kit.libraries);
        Path run = folder.resolve("ray1-grader/run");
        assertEquals("rwxr-xr-x", PosixFilePermissions.toString(Files.getPosixFilePermissions(run)));
        assertTrue(Files.readString(run).startsWith("#!/usr/bin/env bash\n"));
        assertTrue(Files.readString(folder.resolve("Dockerfile")).contains("FROM eclipse-temurin:17-jdk\n"));
        Map<String, Object> options = (Map<String, Object>) new Gson()
                .fromJson(Files.readString(folder.resolve("info.json")), Map.class).get("externalGradingOptions");
        assertEquals("example/ray1-grader:test", options.get("image"));
        assertEquals("/ray1-grader/run", options.get("entrypoint"));
        assertEquals("hidden tests show as a summary per task by default", Map.of("RAY1_HIDDEN_TESTS", "summary"),
                options.get("environment"));
        // The cylinder is extra credit (its tests are all bonus tests): optional, found from the tests.
        String readme = Files.readString(folder.resolve("README.md"));
        assertTrue(readme, readme.contains("<pl-file-upload file-names=\"ClampTexture.java,Group.java,OrthographicCamera.java,"
                + "PerspectiveCamera.java,RepeatTexture.java,Sphere.java,Triangle.java\" optional-file-names=\"Cylinder.java\">"));

        Path root = FOLDER.getRoot().toPath().resolve("grade");
        KitInputs.writeSubmissionWithStubbedSphere(root.resolve("student"));
        // Left out, as the optional file may be: graded as the untouched stub, which costs no regular point.
        Files.delete(root.resolve("student/Cylinder.java"));
        assertEquals(0, KitInputs.runScript(run, "GRADE_ROOT", root, FOLDER.getRoot().toPath().resolve("run.log")));

        Map<String, Object> results = new Gson().fromJson(Files.readString(root.resolve("results/results.json")), Map.class);
        assertEquals(true, results.get("gradable"));
        assertTrue((String) results.get("output"), ((String) results.get("output")).contains(
                "Not found in the submission (graded as the untouched handout): src/main/java/ray/surface/Cylinder.java"));
        double score = (Double) results.get("score");
        assertTrue("score " + score, score > 0 && score < 1);
        double[] points = new double[7];
        double[] possible = new double[7];
        for (Map<String, Object> t : (List<Map<String, Object>>) results.get("tests")) {
            String name = (String) t.get("name");
            if (name.endsWith("(bonus)") || !name.startsWith("Task ")) {
                continue;
            }
            int task = Integer.parseInt(name.substring("Task ".length(), name.indexOf(' ', "Task ".length())));
            points[task] += (Double) t.get("points");
            possible[task] += (Double) t.get("max_points");
        }
        assertTrue("Task 2 has points", possible[2] > 0);
        List<String> names = ((List<Map<String, Object>>) results.get("tests")).stream().map(t -> (String) t.get("name")).toList();
        assertTrue(names.toString(), names.contains("Task 2 (Sphere): hidden tests") && names.stream().noneMatch(n -> n.startsWith("Hidden test")));
        assertEquals("a stubbed sphere scores nothing in Task 2", 0, points[2], 0);
        for (int task : new int[] {1, 3, 4, 5}) {
            assertTrue("task " + task + " has points", possible[task] > 0);
            assertEquals("task " + task + " keeps its points", possible[task], points[task], 0);
        }
        // The stubbed sphere's failed render shows its pictures: the render, the reference and their difference.
        Map<String, Object> render = ((List<Map<String, Object>>) results.get("tests")).stream()
                .filter(t -> ((String) t.get("name")).contains("SphereRenderTest.rendersLikeTheReference[one-sphere]"))
                .findFirst().orElseThrow();
        List<Map<String, Object>> images = (List<Map<String, Object>>) render.get("images");
        assertEquals(3, images.size());
        assertEquals("your render", images.get(0).get("label"));
        assertTrue(((String) images.get(0).get("url")).startsWith("data:image/png;base64,"));
    }
}
