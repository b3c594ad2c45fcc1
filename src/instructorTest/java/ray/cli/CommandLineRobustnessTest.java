package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Limits and output problems on the command line: one line each, a non-zero exit status, and a
 * stack trace only for an unexpected failure and only with --verbose.
 */
public class CommandLineRobustnessTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Path root;
    private Path scene;

    @Before
    public void setUp() throws Exception {
        root = folder.getRoot().toPath();
        scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
    }

    @Test
    public void samplesAboveTheLimitAreAUsageError() {
        for (String command : new String[] {"render", "trace"}) {
            CliRun run = command.equals("render") ? CliRun.of("render", "--samples", "65537", "-o", root.resolve("out").toString(),
                    scene.toString()) : CliRun.of("trace", "--samples", "65537", scene.toString(), "0", "0");
            assertEquals(run.toString(), 2, run.status);
            assertEquals(run.toString(), "--samples must be at most 65536, got 65537", CliRun.lines(run.err)[0]);
            run.assertNoStackTrace();
        }
        assertTrue("nothing is rendered", !Files.exists(root.resolve("out")));
    }

    @Test
    public void referenceSamplesAboveTheLimitAreAUsageError() {
        CliRun run = CliRun.of("accuracy", "--reference-samples", "70000", scene.toString());
        assertEquals(run.toString(), 2, run.status);
        assertEquals(run.toString(), "--reference-samples must be at most 65536, got 70000", CliRun.lines(run.err)[0]);
    }

    @Test
    public void outputThatIsAFileIsRefusedAndLeftAlone() throws Exception {
        Path file = CliRun.write(root.resolve("notes.txt"), "mine");
        CliRun run = CliRun.of("render", "-o", file.toString(), scene.toString());
        assertEquals(run.toString(), 1, run.status);
        assertEquals(run.toString(), "error: " + file + " is a file; expected a folder (-o DIR)", run.err.strip());
        assertEquals("mine", Files.readString(file));
    }

    @Test
    public void aFileWhereTheCameraRaysFolderGoesIsRefusedAndLeftAlone() throws Exception {
        Path out = root.resolve("out");
        Path file = CliRun.write(out.resolve("camera-rays"), "mine");
        CliRun run = CliRun.of("render", "--camera-rays", "-o", out.toString(), scene.toString());
        assertEquals(run.toString(), 1, run.status);
        assertEquals(run.toString(), "error: " + file + " is a file; expected a folder (-o DIR)", run.err.strip());
        assertEquals("mine", Files.readString(file));
    }

    /** A folder where the PNG should go cannot be replaced by it: an I/O failure the command did not foresee. */
    @Test
    public void unexpectedFailureIsOneLineAndVerboseAddsTheStackTrace() throws Exception {
        Path out = root.resolve("out");
        CliRun.write(out.resolve("floor.png/keep.txt"), "a folder in the way");
        CliRun quiet = CliRun.of("render", "-o", out.toString(), scene.toString());
        assertEquals(quiet.toString(), 1, quiet.status);
        String[] lines = CliRun.lines(quiet.err);
        assertEquals(quiet.toString(), 2, lines.length);
        assertTrue(quiet.toString(), lines[0].startsWith("error: " + scene + ": "));
        assertTrue(quiet.toString(), lines[0].endsWith("; --verbose shows the stack trace)"));
        assertEquals("1 of 1 scenes failed", lines[1]);
        quiet.assertNoStackTrace();

        CliRun verbose = CliRun.of("render", "--verbose", "-o", out.toString(), scene.toString());
        assertEquals(1, verbose.status);
        String[] verboseLines = verbose.err.split("\\R");
        assertTrue(verbose.toString(), verboseLines[0].startsWith("error: " + scene + ": FileSystemException: "));
        assertTrue(verbose.toString(), verboseLines[1].startsWith("java.nio.file.FileSystemException: "));
        assertTrue(verbose.toString(), verbose.err.contains("\tat ray.image.PngWriter.write("));
        assertTrue("the folder in the way is untouched", Files.exists(out.resolve("floor.png/keep.txt")));
    }
}
