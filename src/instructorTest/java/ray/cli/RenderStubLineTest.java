package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.render.TaskProbes;
import ray.render.TaskProbes.Part;
import ray.variants.StubBuild;

/**
 * The line {@code ray1 render} ends with while tasks are still the handout's stubs: once per run
 * (not per scene), last, in either mode, and never with the solution.
 */
public class RenderStubLineTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final String ALL_STUBS_LINE = TaskProbes.stillStubsLine(java.util.EnumSet.allOf(Part.class));

    /** The handout's stubs of every student file, as a student first runs them. */
    private static Path handoutClasses;
    private static List<String> scenes;

    @BeforeClass
    public static void compileTheHandoutsStubs() throws Exception {
        Map<String, String> stubs = new LinkedHashMap<>();
        for (Part part : Part.values()) {
            stubs.put(part.file, StubBuild.stubOf(part.file));
        }
        Path root = FOLDER.getRoot().toPath();
        handoutClasses = StubBuild.compile(stubs, root.resolve("handout"));
        scenes = new ArrayList<>();
        for (String name : List.of("a", "b", "c")) {
            scenes.add(CliRun.write(root.resolve("scenes/" + name + ".xml"), CliRun.floorScene("")).toString());
        }
    }

    @Test
    public void aStubRenderEndsWithTheLineOnce() throws Exception {
        String[] run = renderWithTheStubs("render", "-o", FOLDER.getRoot().toPath().resolve("out").toString(), scenes.get(0),
                scenes.get(1), scenes.get(2));
        assertEquals(run[2], "0", run[0]);
        String whole = run[1] + run[2];
        assertEquals(whole, 1, occurrences(whole, "Still stubs:"));
        assertEquals(whole, 1, occurrences(whole, ALL_STUBS_LINE));
        String[] lines = CliRun.lines(run[1]);
        // Three scenes, each a summary and a plan line, then the stubs.
        assertEquals(whole, 7, lines.length);
        assertEquals(ALL_STUBS_LINE, lines[6]);
        assertEquals("", run[2]);
    }

    @Test
    public void cameraRaysEndWithItToo() throws Exception {
        String[] run = renderWithTheStubs("render", "--camera-rays", "-o", FOLDER.getRoot().toPath().resolve("rays").toString(),
                scenes.get(0), scenes.get(1));
        assertEquals(run[2], "0", run[0]);
        String[] lines = CliRun.lines(run[1]);
        assertEquals(run[1], 3, lines.length);
        assertEquals(ALL_STUBS_LINE, lines[2]);
        assertEquals(1, occurrences(run[1] + run[2], "Still stubs:"));
    }

    /** A scene that fails does not hide the line, nor the failure count. */
    @Test
    public void aFailedSceneStillEndsWithTheLine() throws Exception {
        Path broken = CliRun.write(FOLDER.getRoot().toPath().resolve("broken/broken.xml"), CliRun.BROKEN_SCENE);
        String[] run = renderWithTheStubs("render", "-o", FOLDER.getRoot().toPath().resolve("out-broken").toString(), scenes.get(0),
                broken.toString());
        assertEquals(run[2], "1", run[0]);
        assertTrue(run[2], run[2].endsWith("1 of 2 scenes failed\n"));
        String[] lines = CliRun.lines(run[1]);
        assertEquals(ALL_STUBS_LINE, lines[lines.length - 1]);
        assertEquals(1, occurrences(run[1] + run[2], "Still stubs:"));
    }

    /** With every task finished (this tree's solution), no word about stubs. */
    @Test
    public void theSolutionGetsNoLine() throws Exception {
        CliRun run = CliRun.of("render", "-o", FOLDER.getRoot().toPath().resolve("solution").toString(), scenes.get(0), scenes.get(1));
        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), 4, CliRun.lines(run.out).length);
        assertFalse(run.toString(), (run.out + run.err).contains("stub"));
        CliRun rays = CliRun.of("render", "--camera-rays", "-o", FOLDER.getRoot().toPath().resolve("solution").toString(), scenes.get(0));
        assertEquals(rays.toString(), 1, CliRun.lines(rays.out).length);
        assertFalse(rays.toString(), (rays.out + rays.err).contains("stub"));
    }

    /** {@code ray1 ARGS} run with the handout's stubs in place: its status, standard output and standard error. */
    private static String[] renderWithTheStubs(String... args) throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status;
        try (URLClassLoader loader = StubBuild.loader(List.of(handoutClasses));
                PrintWriter o = new PrintWriter(out); PrintWriter e = new PrintWriter(err)) {
            Class<?> command = loader.loadClass(Ray1Command.class.getName());
            assertFalse("the loader gave this JVM's Ray1Command", command == Ray1Command.class);
            status = (Integer) command.getMethod("run", PrintWriter.class, PrintWriter.class, String[].class).invoke(null, o, e, args);
        }
        return new String[] {String.valueOf(status), out.toString(), err.toString()};
    }

    private static int occurrences(String text, String part) {
        int count = 0;
        for (int at = text.indexOf(part); at >= 0; at = text.indexOf(part, at + 1)) {
            count++;
        }
        return count;
    }
}
