package ray.testing;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.junit.runner.Request;
import ray.endtoend.TextureRenderTest;

/**
 * A render test class run as an IDE runs it, in a JVM of its own whose working folder is not the
 * project: JUnit's console runner on this JVM's class path, from a folder outside the project and
 * from one inside it. Before {@link ProjectFolder}, every render test failed there with a missing
 * scenes/ folder. The class is {@link TextureRenderTest}, the fastest render test class (two scenes,
 * about a second), which also reads textures by paths relative to its scenes.
 */
public class RenderTestsFromOtherFoldersTest {
    private static final String TEST_CLASS = TextureRenderTest.class.getName();
    private static final int LIMIT_SECONDS = 120;

    @Rule
    public final TemporaryFolder temporary = new TemporaryFolder();

    /** What JUnitCore printed and its exit code (0: every test passed). */
    private record Run(int exit, String output) {
        @Override
        public String toString() {
            return "exit " + exit + ", output:\n" + output;
        }
    }

    private static Run junit(Path workingFolder, String classPath, Path log) throws IOException, InterruptedException {
        List<String> command = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx512m",
                "-Djava.awt.headless=true", "-cp", classPath, "org.junit.runner.JUnitCore", TEST_CLASS);
        Process process = new ProcessBuilder(command).directory(workingFolder.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        if (!process.waitFor(LIMIT_SECONDS, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
            throw new AssertionError(TEST_CLASS + " took more than " + LIMIT_SECONDS + " s in " + workingFolder);
        }
        return new Run(process.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
    }

    /** How many tests the class has (one per scene), as JUnit counts them here. */
    private static int testCount() {
        return Request.aClass(TextureRenderTest.class).getRunner().testCount();
    }

    private static void assertAllPassed(Run run) {
        int count = testCount();
        assertTrue("the class has no tests", count > 0);
        assertEquals(run.toString(), 0, run.exit());
        assertTrue(run.toString(), run.output().contains("OK (" + count + " test" + (count == 1 ? "" : "s") + ")"));
    }

    @Test
    public void fromAFolderOutsideTheProject() throws Exception {
        // Outside the project and with a space in its name, as a Windows user's workspace may be.
        Path working = Files.createDirectories(temporary.getRoot().toPath().resolve("ide workspace"));
        Path project = ProjectFolder.get();
        assertFalse(working + " is inside the project", working.toAbsolutePath().startsWith(project));
        Path runFile = project.resolve("build/reports/render-diff/TextureRenderTest/run.txt");
        Files.deleteIfExists(runFile);

        assertAllPassed(junit(working, System.getProperty("java.class.path"), temporary.newFile("outside.log").toPath()));

        // The report went to the project's build folder, one line per scene, and nothing was written here.
        List<String> rendered = Files.readAllLines(runFile, StandardCharsets.UTF_8);
        assertEquals(rendered.toString(), testCount(), rendered.size());
        assertTrue(rendered.toString(), rendered.stream().allMatch(line -> line.endsWith("=true")));
        try (Stream<Path> files = Files.list(working)) {
            assertEquals(List.of(), files.collect(Collectors.toList()));
        }
    }

    @Test
    public void fromASubfolderOfTheProject() throws Exception {
        assertAllPassed(junit(ProjectFolder.resolve("src"), System.getProperty("java.class.path"),
                temporary.newFile("src.log").toPath()));
    }

    @Test
    public void withTheTestClassesOutsideTooItFailsWithOneLineSayingWhy() throws Exception {
        // The test classes copied out of the project, and run from outside it: nothing leads back.
        Path classes = Path.of(ProjectFolder.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Path copy = temporary.newFolder("copied classes").toPath();
        copyTree(classes, copy);
        List<String> classPath = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            classPath.add(Path.of(entry).toAbsolutePath().equals(classes.toAbsolutePath()) ? copy.toString() : entry);
        }
        assertTrue("the test classes " + classes + " are not on the class path", classPath.contains(copy.toString()));
        Path working = temporary.newFolder("elsewhere").toPath();

        Run run = junit(working, String.join(File.pathSeparator, classPath), temporary.newFile("nowhere.log").toPath());

        assertEquals(run.toString(), 1, run.exit());
        String expected = "ray.testing.NotThisTasksFault: cannot find the ray1 project folder (the one with scenes/ and "
                + "settings.gradle) in or above the working folder " + working + " or the test classes' folder " + copy
                + "; open the ray1 folder itself in your IDE, or run the tests from it";
        assertTrue(run.toString(), run.output().lines().anyMatch(expected::equals));
        // It fails the class once, before any scene is rendered, rather than each test with its own trace.
        assertTrue(run.toString(), run.output().contains("Tests run: 0,  Failures: 1"));
    }

    private static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> walk = Files.walk(from)) {
            for (Path p : walk.collect(Collectors.toList())) {
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(p, target);
                }
            }
        }
    }
}
