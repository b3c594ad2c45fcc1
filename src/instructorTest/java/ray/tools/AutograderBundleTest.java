package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.google.gson.Gson;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Enumeration;
import java.util.List;
import java.util.Map;
import org.apache.commons.compress.archivers.zip.ZipArchiveEntry;
import org.apache.commons.compress.archivers.zip.ZipFile;
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
        unpack(zip, root.resolve("source"));
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

    /** Unzips with each entry's Unix mode, as Gradescope's unzip keeps it. */
    private static void unpack(Path zip, Path target) throws Exception {
        try (ZipFile file = ZipFile.builder().setPath(zip).get()) {
            Enumeration<ZipArchiveEntry> entries = file.getEntries();
            while (entries.hasMoreElements()) {
                ZipArchiveEntry entry = entries.nextElement();
                Path out = target.resolve(entry.getName());
                Files.createDirectories(out.getParent());
                try (InputStream in = file.getInputStream(entry)) {
                    Files.copy(in, out);
                }
                if (entry.getUnixMode() != 0) {
                    Files.setPosixFilePermissions(out, PosixFilePermissions.fromString(modeString(entry.getUnixMode() & 0777)));
                }
            }
        }
    }

    private static String modeString(int mode) {
        StringBuilder s = new StringBuilder();
        for (int shift = 6; shift >= 0; shift -= 3) {
            int bits = (mode >> shift) & 7;
            s.append((bits & 4) != 0 ? 'r' : '-').append((bits & 2) != 0 ? 'w' : '-').append((bits & 1) != 0 ? 'x' : '-');
        }
        return s.toString();
    }
}
