package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.judge.Containment;

/**
 * Ending a worker's user ends all it started, however it hid (its own session, a stopped process,
 * one that ignores signals, a RAY1_SANDBOX it named itself), and removes what it wrote where everyone
 * may write; the setup file reads back as written, and a line it does not know is an error.
 */
public class ContainmentTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void theSetupReadsBackAsWritten() throws Exception {
        Containment written = new Containment(List.of("java", "-cp", "a b:c", "Main"), new java.util.TreeMap<>(Map.of("HOME", "/h", "X", "1=2")), "ray1-student");
        Path file = folder.getRoot().toPath().resolve("task-2");
        written.write(file);
        assertEquals(Files.readString(file), String.join("\n", "command java", "command -cp", "command a b:c", "command Main",
                "env HOME=/h", "env X=1=2", "user ray1-student", ""));
        Containment read = Containment.read(file);
        Path again = folder.getRoot().toPath().resolve("again");
        read.write(again);
        assertEquals(Files.readString(file), Files.readString(again));
        Files.writeString(file, "command java\nrun as root\n");
        java.io.IOException e = org.junit.Assert.assertThrows(java.io.IOException.class, () -> Containment.read(file));
        assertEquals(file + ": a line the judge does not know: run as root", e.getMessage());
    }

    @Test(timeout = 120_000)
    public void everyProcessAndFileOfTheUserIsGoneAfterwards() throws Exception {
        assumeTrue("needs root and the user " + Sandbox.USER, Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent()
                && Sandbox.command("setpriv") != null);
        try (UserClaim claim = UserClaim.tryClaim(Sandbox.USER)) {
            assumeTrue("another grading on this machine holds " + Sandbox.USER, claim != null);
            int[] ids = Sandbox.lookUp(Sandbox.USER).get();
            // The student's user must reach its home through the temporary folder (which only root may list).
            Files.setPosixFilePermissions(folder.getRoot().toPath(), java.nio.file.attribute.PosixFilePermissions.fromString("rwx--x--x"));
            Path home = folder.newFolder("home").toPath();
            Files.setOwner(home, home.getFileSystem().getUserPrincipalLookupService().lookupPrincipalByName(Sandbox.USER));
            String marker = "ray1-containment-test-" + ProcessHandle.current().pid();
            String script = "touch " + home + "/left; mkdir /tmp/" + marker + "; touch /tmp/" + marker + "/inside;"
                    + " setsid bash -c 'export RAY1_SANDBOX=$HOME; sleep 1000' </dev/null >/dev/null 2>&1 &"
                    + " (trap '' TERM HUP INT; sleep 1000) </dev/null >/dev/null 2>&1 &"
                    + " (sleep 1000 & kill -STOP $!; wait) </dev/null >/dev/null 2>&1 &"
                    + " echo started; sleep 1000";
            List<String> command = List.of(Sandbox.command("setpriv"), "--reuid=" + ids[0], "--regid=" + ids[1], "--clear-groups",
                    "--", "bash", "-c", script);
            Containment containment = new Containment(command, Map.of("HOME", home.toString()), Sandbox.USER);
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            assertEquals("started", new String(p.getInputStream().readNBytes(7)));
            Thread.sleep(500);
            assertTrue("its processes run: " + StudentUserProcesses.living(Sandbox.USER), StudentUserProcesses.living(Sandbox.USER).size() >= 5);
            assertTrue(Files.exists(Path.of("/tmp", marker, "inside")));
            assertTrue(containment.endUsersProcesses() >= 5);
            assertTrue(p.waitFor(10, java.util.concurrent.TimeUnit.SECONDS));
            containment.removeUsersFiles();
            assertEquals(List.of(), StudentUserProcesses.livingAfter(Sandbox.USER, 10));
            assertFalse("its file in the shared temporary folder", Files.exists(Path.of("/tmp", marker)));
            assertFalse("its file in its home", Files.exists(home.resolve("left")));
            assertTrue("its home itself stays", Files.isDirectory(home));
        }
    }
}
