package ray.cli;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;

import com.google.gson.JsonParser;
import java.nio.file.Files;
import java.nio.file.Path;
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

        // The radius element is on line 5; column 13 is where its start tag ends.
        assertArrayEquals(run.toString(), new String[] {
            "error: " + broken + ":5:13: radius is -1.0; expected a positive number",
            "1 of 3 scenes failed",
        }, CliRun.lines(run.err));

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
        assertArrayEquals(run.toString(), new String[] {
            "error: " + missing + ":1:1: no such file; expected the path of a scene file",
            "1 of 2 scenes failed",
        }, CliRun.lines(run.err));
        assertTrue("the good scene still renders", Files.isRegularFile(output.resolve("good.png")));
        assertFalse(Files.exists(output.resolve("nowhere.png")));
        run.assertNoStackTrace();
    }

    @Test
    public void malformedXmlIsLocated() throws Exception {
        Path bad = CliRun.write(root.resolve("bad.xml"), "<scene>\n  <image>4 4</image>\n  <oops>\n</scene>\n");
        CliRun run = CliRun.of("render", "-o", output.toString(), bad.toString());
        assertNotEquals(run.toString(), 0, run.status);
        // The parser stops at "</scene>" on line 4; the error is where <oops> was left open, line 3.
        assertArrayEquals(run.toString(), new String[] {
            "error: " + bad + ":3:3: malformed XML: <oops> is never closed (found </scene> at 4:1); expected </oops> before it",
            "1 of 1 scenes failed",
        }, CliRun.lines(run.err));
        assertFalse(Files.exists(output.resolve("bad.png")));
        run.assertNoStackTrace();
    }

    @Test
    public void zeroSamplesIsRejectedWithAClearMessage() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "--samples", "0", "-o", output.toString(), scene.toString());
        assertNotEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), "--samples must be at least 1, got 0", CliRun.lines(run.err)[0]);
        assertFalse("nothing is rendered", Files.exists(output));
        run.assertNoStackTrace();
    }

    @Test
    public void zeroThreadsIsRejectedWithAClearMessage() throws Exception {
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        CliRun run = CliRun.of("render", "--threads", "0", "-o", output.toString(), scene.toString());
        assertNotEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), "--threads must be at least 1, got 0", CliRun.lines(run.err)[0]);
        assertFalse(Files.exists(output));
        run.assertNoStackTrace();
    }

    @Test
    public void nonNumericSamplesIsRejected() throws Exception {
        CliRun run = CliRun.of("render", "--samples", "many", "-o", output.toString(), "x.xml");
        assertNotEquals(run.toString(), 0, run.status);
        // Picocli's own words.
        assertEquals(run.toString(), "Invalid value for option '--samples': 'many' is not an int", CliRun.lines(run.err)[0]);
        run.assertNoStackTrace();
    }

    @Test
    public void noArgumentsPrintsUsage() {
        CliRun run = CliRun.of();
        assertNotEquals(run.toString(), 0, run.status);
        String[] errors = CliRun.lines(run.err);
        assertEquals(run.toString(), "a command is required, e.g. ray1 render scenes/", errors[0]);
        assertTrue(run.toString(), errors[1].startsWith("Usage: ray1 "));
        assertTrue(run.toString(), run.err.contains("render"));
        run.assertNoStackTrace();
    }

    @Test
    public void renderWithoutScenesPrintsUsage() {
        CliRun run = CliRun.of("render");
        assertNotEquals(run.toString(), 0, run.status);
        String[] errors = CliRun.lines(run.err);
        assertEquals(run.toString(), "Missing required parameter: 'SCENE.xml|DIR'", errors[0]);
        assertTrue(run.toString(), errors[1].startsWith("Usage: ray1 render "));
        run.assertNoStackTrace();
    }

    @Test
    public void folderWithoutScenesIsAnError() throws Exception {
        Path empty = Files.createDirectories(root.resolve("empty"));
        CliRun run = CliRun.of("render", "-o", output.toString(), empty.toString());
        assertNotEquals(run.toString(), 0, run.status);
        assertArrayEquals(run.toString(), new String[] {"error: no scene files (*.xml) found in [" + empty + "]"},
                CliRun.lines(run.err));
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
        assertArrayEquals(run.toString(), new String[] {
            "error: " + second + ": renders to " + output.resolve("same.png") + ", as " + first + " does; rename one",
            "1 of 2 scenes failed",
        }, CliRun.lines(run.err));
        run.assertNoStackTrace();
    }
}
