package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;

import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.regex.Pattern;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * {@code ray1} on bad input: a broken or missing scene is reported in one located line while the
 * others still render; bad options and a missing command print usage; no stack traces anywhere.
 */
public class RenderCommandErrorsTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Path root;
    private Path output;

    @Before
    public void setUp() {
        root = folder.getRoot().toPath();
        output = root.resolve("out");
    }

    private static long count(String[] lines, String prefix) {
        return Arrays.stream(lines).filter(l -> l.startsWith(prefix)).count();
    }

    @Test
    public void brokenSceneAmongGoodOnesIsReportedOnceAndTheOthersRender() throws Exception {
        CliRun.write(root.resolve("scenes/a-good.xml"), CliRun.floorScene(""));
        Path broken = CliRun.write(root.resolve("scenes/b-broken.xml"), CliRun.BROKEN_SCENE);
        CliRun.write(root.resolve("scenes/c-good.xml"), CliRun.floorScene(""));
        Path stats = root.resolve("stats.json");
        CliRun run = CliRun.of("render", "--stats", stats.toString(), "-o", output.toString(), root.resolve("scenes").toString());

        assertNotEquals(run.toString(), 0, run.status);
        assertTrue(Files.isRegularFile(output.resolve("a-good.png")));
        assertTrue(Files.isRegularFile(output.resolve("c-good.png")));
        assertFalse("no PNG for the broken scene", Files.exists(output.resolve("b-broken.png")));
        // A summary line and a plan line per scene that rendered.
        assertEquals(run.toString(), 4, CliRun.lines(run.out).length);

        String[] errors = CliRun.lines(run.err);
        assertEquals(run.toString(), 1, count(errors, "error: "));
        // The radius element is on line 5; the column is where its start tag ends.
        Pattern located = Pattern.compile("error: " + Pattern.quote(broken.toString()) + ":5:\\d+: .*radius.*");
        assertTrue(run.toString(), located.matcher(errors[0]).matches());
        assertEquals(run.toString(), "1 of 3 scenes failed", errors[errors.length - 1]);

        assertEquals("the stats list the scenes that rendered", 2,
                JsonParser.parseString(Files.readString(stats)).getAsJsonArray().size());
        run.assertNoStackTrace();
    }

    @Test
    public void missingSceneFileIsAnErrorLine() throws Exception {
        Path missing = root.resolve("nowhere.xml");
        Path good = CliRun.write(root.resolve("good.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "-o", output.toString(), missing.toString(), good.toString());

        assertNotEquals(run.toString(), 0, run.status);
        String[] errors = CliRun.lines(run.err);
        assertEquals(run.toString(), 1, count(errors, "error: "));
        assertTrue(run.toString(), errors[0].startsWith("error: " + missing + ":1:1: "));
        assertTrue(run.toString(), errors[0].contains("no such file"));
        assertTrue("the good scene still renders", Files.isRegularFile(output.resolve("good.png")));
        assertFalse(Files.exists(output.resolve("nowhere.png")));
        run.assertNoStackTrace();
    }

    @Test
    public void malformedXmlIsLocated() throws Exception {
        Path bad = CliRun.write(root.resolve("bad.xml"), "<scene>\n  <image>4 4</image>\n  <oops>\n</scene>\n");
        CliRun run = CliRun.of("render", "-o", output.toString(), bad.toString());
        assertNotEquals(run.toString(), 0, run.status);
        assertTrue(run.toString(), CliRun.lines(run.err)[0].matches("error: " + Pattern.quote(bad.toString()) + ":\\d+:\\d+: .+"));
        assertFalse(Files.exists(output.resolve("bad.png")));
        run.assertNoStackTrace();
    }

    @Test
    public void zeroSamplesIsRejectedWithAClearMessage() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "--samples", "0", "-o", output.toString(), scene.toString());
        assertNotEquals(run.toString(), 0, run.status);
        assertTrue(run.toString(), run.err.contains("--samples must be at least 1, got 0"));
        assertFalse("nothing is rendered", Files.exists(output));
        run.assertNoStackTrace();
    }

    @Test
    public void zeroThreadsIsRejectedWithAClearMessage() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "--threads", "0", "-o", output.toString(), scene.toString());
        assertNotEquals(run.toString(), 0, run.status);
        assertTrue(run.toString(), run.err.contains("--threads must be at least 1, got 0"));
        assertFalse(Files.exists(output));
        run.assertNoStackTrace();
    }

    @Test
    public void nonNumericSamplesIsRejected() throws Exception {
        CliRun run = CliRun.of("render", "--samples", "many", "-o", output.toString(), "x.xml");
        assertNotEquals(run.toString(), 0, run.status);
        assertTrue(run.toString(), run.err.contains("--samples"));
        run.assertNoStackTrace();
    }

    @Test
    public void noArgumentsPrintsUsage() {
        CliRun run = CliRun.of();
        assertNotEquals(run.toString(), 0, run.status);
        assertTrue(run.toString(), run.err.contains("Usage: ray1"));
        assertTrue(run.toString(), run.err.contains("render"));
        run.assertNoStackTrace();
    }

    @Test
    public void renderWithoutScenesPrintsUsage() {
        CliRun run = CliRun.of("render");
        assertNotEquals(run.toString(), 0, run.status);
        assertTrue(run.toString(), run.err.contains("Usage: ray1 render"));
        run.assertNoStackTrace();
    }

    @Test
    public void folderWithoutScenesIsAnError() throws Exception {
        Path empty = Files.createDirectories(root.resolve("empty"));
        CliRun run = CliRun.of("render", "-o", output.toString(), empty.toString());
        assertNotEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), 1, count(CliRun.lines(run.err), "error: "));
        run.assertNoStackTrace();
    }

    @Test
    public void twoScenesWithTheSameNameDoNotOverwriteEachOther() throws Exception {
        Path first = CliRun.write(root.resolve("one/same.xml"), CliRun.floorScene(""));
        Path second = CliRun.write(root.resolve("two/same.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "-o", output.toString(), first.toString(), second.toString());
        assertNotEquals(run.toString(), 0, run.status);
        // One scene rendered: its summary line and its plan line.
        assertEquals(run.toString(), 2, CliRun.lines(run.out).length);
        String[] errors = CliRun.lines(run.err);
        assertEquals(run.toString(), 1, count(errors, "error: "));
        assertTrue(run.toString(), errors[0].startsWith("error: " + second));
        run.assertNoStackTrace();
    }
}
