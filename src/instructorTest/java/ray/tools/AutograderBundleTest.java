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
 * The Gradescope bundle works as Gradescope uses it: unpacked into a folder laid out like
 * /autograder (source/ holds the zip, submission/ the student's files; AUTOGRADER_ROOT names the
 * folder), its run_autograder grades the submission into results/results.json with java alone. Here
 * the submission is the solution with a stubbed sphere: Task 2 scores nothing, every other task full.
 */
public class AutograderBundleTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void runAutograderGradesASubmissionIntoResultsJson() throws Exception {
        Path root = FOLDER.getRoot().toPath().resolve("autograder");
        Path zip = FOLDER.getRoot().toPath().resolve("ray1-gradescope.zip");
        KitInputs kit = new KitInputs();
        AutograderBundle.build(Path.of("."), zip, kit.classes, kit.libraries);
        KitInputs.unpack(zip, root.resolve("source"));
        assertEquals("rwxr-xr-x", PosixFilePermissions.toString(Files.getPosixFilePermissions(root.resolve("source/run_autograder"))));
        assertEquals("rwxr-xr-x", PosixFilePermissions.toString(Files.getPosixFilePermissions(root.resolve("source/setup.sh"))));
        assertTrue(Files.readString(root.resolve("source/run_autograder")).startsWith("#!/usr/bin/env bash\n"));

        KitInputs.writeSubmissionWithStubbedSphere(root.resolve("submission"));
        assertEquals(0, KitInputs.runScript(root.resolve("source/run_autograder"), "AUTOGRADER_ROOT", root,
                FOLDER.getRoot().toPath().resolve("run.log")));

        Map<String, Object> results = new Gson().fromJson(Files.readString(root.resolve("results/results.json")), Map.class);
        double[] regular = new double[7];
        double[] possible = new double[7];
        for (Map<String, Object> t : (List<Map<String, Object>>) results.get("tests")) {
            if (((List<String>) t.get("tags")).contains("bonus")) {
                continue;
            }
            int task = Integer.parseInt(((String) t.get("number")).split("\\.")[0]);
            regular[task] += (Double) t.get("score");
            possible[task] += (Double) t.get("max_score");
        }
        assertEquals("a stubbed sphere scores nothing in Task 2", 0, regular[2], 0);
        for (int task : new int[] {1, 3, 4, 5}) {
            assertTrue("task " + task + " has points", possible[task] > 0);
            assertEquals("task " + task + " keeps its points", possible[task], regular[task], 0);
        }
    }
}
