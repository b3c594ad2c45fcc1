package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** {@code ray1 accuracy}: its options' checks, one-line errors, a batch that goes on past a failure, and the report it writes. */
public class AccuracyCommandTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /** A quick study: two sample counts, a 16-sample reference, a 4×4 window. */
    private static final String[] QUICK = {"--samples", "1,4", "--reference-samples", "16", "--window-size", "4", "--quiet"};

    private CliRun accuracy(String... args) {
        String[] all = new String[args.length + QUICK.length + 1];
        all[0] = "accuracy";
        System.arraycopy(QUICK, 0, all, 1, QUICK.length);
        System.arraycopy(args, 0, all, 1 + QUICK.length, args.length);
        return CliRun.of(all);
    }

    private Path floor() throws Exception {
        return CliRun.write(folder.getRoot().toPath().resolve("floor.xml"), CliRun.floorScene(""));
    }

    @Test
    public void writesTheReportAndSaysWhere() throws Exception {
        Path out = folder.getRoot().toPath().resolve("report");
        CliRun run = accuracy("-o", out.toString(), floor().toString());
        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), "report: " + out.resolve("index.html") + " (1 scene)", run.out.strip());
        assertTrue(Files.isRegularFile(out.resolve("floor/convergence.svg")));
        run.assertNoStackTrace();
    }

    @Test
    public void aSceneWarningGoesToStderrOnceAndTheReportIsStillWritten() throws Exception {
        Path out = folder.getRoot().toPath().resolve("report");
        Path scene = CliRun.write(folder.getRoot().toPath().resolve("floor.xml"), CliRun.floorScene(CliRun.UPSIDE_DOWN_BOX));
        CliRun run = accuracy("-o", out.toString(), scene.toString());
        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), CliRun.upsideDownBoxWarning(scene) + "\n", run.err);
        assertEquals(run.toString(), "report: " + out.resolve("index.html") + " (1 scene)", run.out.strip());
        run.assertNoStackTrace();
    }

    @Test
    public void aFailingSceneDoesNotStopTheOthers() throws Exception {
        Path out = folder.getRoot().toPath().resolve("report");
        Path broken = CliRun.write(folder.getRoot().toPath().resolve("broken.xml"), CliRun.BROKEN_SCENE);
        CliRun run = accuracy("-o", out.toString(), broken.toString(), floor().toString());
        assertEquals(run.toString(), 1, run.status);
        String[] errors = CliRun.lines(run.err);
        assertEquals(run.toString(), 2, errors.length);
        assertTrue(errors[0], errors[0].startsWith("error: " + broken + ":5:"));
        assertEquals("1 of 2 scenes failed", errors[1]);
        assertTrue(run.out, run.out.contains("(1 scene)"));
        run.assertNoStackTrace();
    }

    @Test
    public void aWindowOutsideTheImageIsOneLine() throws Exception {
        Path floor = floor();
        CliRun run = accuracy("--window", "2,2,4,4", "-o", folder.getRoot().toPath().resolve("r").toString(), floor.toString());
        assertEquals(1, run.status);
        assertEquals("error: " + floor + ": the window 2,2,4,4 does not fit in its 4x4 image\n1 of 1 scenes failed", run.err.strip());
    }

    @Test
    public void badOptionsAreRefusedBeforeAnyRender() throws Exception {
        String floor = floor().toString();
        String[][] cases = {
            {"--runs 2", "--runs must be at least 3 (a median with a spread), got 2"},
            {"--samples 4,4", "--samples must be distinct counts, e.g. 1,4,16, got [4, 4]"},
            {"--samples 1,2048", "--samples must lie between 1 and --reference-samples − 1 (1023), got 2048"},
            {"--window 1,2,3", "--window: a window is X,Y,WIDTH,HEIGHT (four integers, Y from the top), got '1,2,3'"},
            {"--window-size 0", "--window-size must be at least 1, got 0"},
            {"--threads 0", "--threads must be at least 1, got 0"},
        };
        for (String[] c : cases) {
            String[] option = c[0].split(" ");
            // Without the quick options: the checks come before any render, whatever the defaults.
            CliRun run = CliRun.of("accuracy", option[0], option[1], floor);
            assertEquals(c[0] + ": " + run, 2, run.status);
            assertEquals(c[0], "", run.out);
            assertTrue(c[0] + ": " + run.err, run.err.startsWith(c[1] + "\n"));
        }
    }

    @Test
    public void theReferenceFolderIsNeverWrittenTo() throws Exception {
        Path references = folder.getRoot().toPath().resolve("refs");
        CliRun.write(references.resolve(RenderCommand.REFERENCE_MARKER), "");
        CliRun run = accuracy("-o", references.toString(), floor().toString());
        assertEquals(1, run.status);
        assertTrue(run.err, run.err.startsWith("error: " + references + " holds the reference images"));
        assertEquals(1, Files.list(references).count());
    }
}
