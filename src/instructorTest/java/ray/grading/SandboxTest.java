package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The sandbox a test JVM runs student code in: as root with the user present, the JVM runs as that
 * user, cannot read a root-only folder, has the compiled classes (hidden tests too) as classes but
 * not as resources, and what it leaves running is ended. Without isolation, the same start-up works
 * as the grader's own user.
 */
public class SandboxTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    /** This JVM's class path: the compiled project (private, sent through the pipe) and the libraries (copied). */
    private static final String CLASSPATH = System.getProperty("java.class.path");

    private static List<String> probe(Sandbox sandbox, Path secret) throws Exception {
        List<String> command = sandbox.command(List.of("-Xmx256m"), CLASSPATH, SandboxProbe.class.getName(),
                List.of(secret.toString(), sandbox.tree().resolve("scenes").toString()));
        ProcessBuilder builder = new ProcessBuilder(command).directory(sandbox.tree().toFile()).redirectErrorStream(true);
        sandbox.environment(builder.environment());
        Process child = builder.start();
        try (java.io.OutputStream in = child.getOutputStream()) {
            Sandbox.writeClasses(CLASSPATH, in);
        }
        String output = new String(child.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(child.waitFor(60, TimeUnit.SECONDS));
        assertEquals(output, 0, child.exitValue());
        return output.lines().collect(Collectors.toList());
    }

    /** The probe's detached sleeps ("sleep 300") running as {@code user}, or as anyone when null. */
    private static long sleepers(String user) {
        return ProcessHandle.allProcesses().filter(p -> p.info().commandLine().map(c -> c.endsWith("sleep 300")).orElse(false))
                .filter(p -> user == null || p.info().user().map(user::equals).orElse(false)).count();
    }

    /** The sleepers of {@code user}, counted again for up to 10 s until there are {@code expected}. */
    private static long sleepersOnceStarted(String user, long expected) throws InterruptedException {
        long deadline = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(10);
        long count = sleepers(user);
        while (count != expected && System.nanoTime() < deadline) {
            Thread.sleep(20);
            count = sleepers(user);
        }
        return count;
    }

    @Test(timeout = 120_000)
    public void isolatedTheJvmRunsAsTheStudentUserAndSeesNoSecret() throws Exception {
        assumeTrue("isolation needs root and the user " + Sandbox.USER, Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent());
        Path secret = folder.newFolder("grader").toPath();
        Files.writeString(secret.resolve("hidden.txt"), "secret", StandardCharsets.UTF_8);
        Files.setPosixFilePermissions(secret, PosixFilePermissions.fromString("rwx------"));
        try (Sandbox sandbox = Sandbox.create(PROJECT, true)) {
            assertTrue(sandbox.isolated());
            assertEquals(null, sandbox.warning());
            List<String> lines = probe(sandbox, secret);
            assertEquals(List.of("user " + Sandbox.USER, "readable " + secret + " false false",
                    "readable " + sandbox.tree().resolve("scenes") + " true true", "class true", "resource false",
                    "loader ray1-graded", "started"), lines);
            // The detached sleep outlived the JVM, as the student's user, until the sandbox ends it.
            assertEquals(1, sleepers(Sandbox.USER));
            assertTrue(sandbox.endStrayProcesses() >= 1);
            assertEquals(0, sleepers(Sandbox.USER));
            // Its library copies hold no class of ray1's own.
            try (Stream<Path> libraries = Files.list(sandbox.tree().resolveSibling("lib"))) {
                for (Path library : libraries.collect(Collectors.toList())) {
                    assertFalse(library.toString(), Sandbox.isPrivateJar(library));
                }
            }
        }
    }

    /** Two graders on one machine share the user: each ends its own strays and spares the other's processes. */
    @Test(timeout = 120_000)
    public void aGraderEndsItsOwnStraysAndSparesAnotherGradersProcesses() throws Exception {
        assumeTrue("isolation needs root and the user " + Sandbox.USER, Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent());
        int[] ids = Sandbox.lookUp(Sandbox.USER).get();
        try (Sandbox mine = Sandbox.create(PROJECT, true); Sandbox theirs = Sandbox.create(PROJECT, true)) {
            ProcessBuilder builder = new ProcessBuilder("setpriv", "--reuid=" + ids[0], "--regid=" + ids[1], "--clear-groups", "--",
                    "sleep", "300");
            theirs.environment(builder.environment());
            Process other = builder.start();
            // setpriv becomes `sleep 300` only once it has set the user and exec'd: wait for that.
            assertEquals(1, sleepersOnceStarted(Sandbox.USER, 1));
            mine.endStrayProcesses();
            assertTrue("another grader's process is spared", other.isAlive());
            theirs.endStrayProcesses();
            assertTrue(other.waitFor(10, TimeUnit.SECONDS));
            assertEquals(0, sleepers(Sandbox.USER));
        }
    }

    @Test(timeout = 120_000)
    public void withoutIsolationTheSameStartUpRunsAsThisUserAndSaysSo() throws Exception {
        Path secret = folder.newFolder("grader").toPath();
        Path root;
        try (Sandbox sandbox = Sandbox.create(PROJECT, false)) {
            root = sandbox.tree().getParent();
            assertFalse(sandbox.isolated());
            assertTrue(sandbox.warning(), sandbox.warning().contains("isolation turned off"));
            long before = sleepers(null);
            List<String> lines = probe(sandbox, secret);
            assertEquals("user " + System.getProperty("user.name"), lines.get(0));
            assertEquals(List.of("class true", "resource false", "loader ray1-graded", "started"), lines.subList(3, 7));
            // A detached process is no descendant by the time the JVM has ended; it is ended in the test instead.
            ProcessHandle.allProcesses().filter(p -> p.info().commandLine().map(c -> c.endsWith("sleep 300")).orElse(false))
                    .filter(p -> p.info().user().map(System.getProperty("user.name")::equals).orElse(false))
                    .forEach(ProcessHandle::destroyForcibly);
            assertTrue(sleepers(null) <= before + 1);
        }
        assertFalse("the sandbox folder is removed", Files.exists(root));
    }

    @Test
    public void aJarWithRayClassesIsPrivateAndALibraryIsNot() throws Exception {
        String junit = Stream.of(CLASSPATH.split(File.pathSeparator)).filter(p -> p.contains("junit-4")).findFirst().orElseThrow();
        assertFalse(Sandbox.isPrivateJar(Path.of(junit)));
        Path jar = folder.getRoot().toPath().resolve("grader.jar");
        try (java.util.jar.JarOutputStream out = new java.util.jar.JarOutputStream(Files.newOutputStream(jar))) {
            out.putNextEntry(new java.util.jar.JarEntry("ray/hidden/Task1HiddenTest.class"));
            out.write(new byte[] {1, 2, 3});
            out.closeEntry();
        }
        assertTrue(Sandbox.isPrivateJar(jar));
    }
}
