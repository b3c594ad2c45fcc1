package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** {@code ray1 explore}'s mistakes of use: each is one line on stderr and exit status 1 (or 2), never a server. */
public class ExploreCommandTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void aSceneThatDoesNotLoadIsOneLineWithItsPlace() throws Exception {
        Path scene = folder.getRoot().toPath().resolve("bad.xml");
        Files.writeString(scene, "<scene>\n  <radus>1</radus>\n</scene>\n");
        CliRun run = CliRun.of("explore", "--port", "0", scene.toString());
        assertEquals(run.toString(), 1, run.status);
        assertTrue(run.err, run.err.startsWith("error: " + scene + ":2:"));
        assertEquals(run.err, 1, CliRun.lines(run.err).length);
        run.assertNoStackTrace();
        CliRun missing = CliRun.of("explore", "--port", "0", "scenes/no-such.xml");
        assertEquals(missing.toString(), 1, missing.status);
        assertTrue(missing.err, missing.err.startsWith("error: scenes/no-such.xml"));
    }

    @Test
    public void aTakenPortSaysHowToChooseAnother() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CliRun run = CliRun.of("explore", "--port", String.valueOf(taken.getLocalPort()), "scenes/one-sphere.xml");
            assertEquals(run.toString(), 1, run.status);
            assertEquals("error: port " + taken.getLocalPort() + " is in use (another ray1 explore?); choose another with --port N,"
                    + " or --port 0 for any free one\n", run.err);
        }
    }

    @Test
    public void badOptionsAreRefusedBeforeAnythingRenders() {
        CliRun port = CliRun.of("explore", "--port", "70000", "scenes/one-sphere.xml");
        assertEquals(port.toString(), 2, port.status);
        assertTrue(port.err, port.err.contains("--port must be from 0 to 65535, but was 70000"));
        CliRun reference = CliRun.of("explore", "--port", "0", "--reference", "nowhere.png", "scenes/one-sphere.xml");
        assertEquals(reference.toString(), 1, reference.status);
        assertEquals("error: --reference nowhere.png: no such file; expected a PNG image\n", reference.err);
    }
}
