package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;

import com.google.gson.Gson;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;
import ray.grading.Grader;
import ray.grading.StudentFiles;

/**
 * The students' {@code gradle submission} (gradle/submission.gradle), run with real Gradle in a built
 * handout as a student runs it: its zip holds exactly the files the grader takes, at their project
 * paths, with their checksums, and the grader gives it full marks when they are the solution's; a file
 * that does not compile is refused in one line and leaves no zip. The task is Groovy in the build, so
 * it runs in a Gradle process: the Gradle and the Java that run this test (instructor.gradle passes
 * them as ray1.gradleHome and ray1.gradleJavaHome), else the `gradle` on the PATH.
 */
public class SubmissionZipTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));
    private static final String SPHERE = "src/main/java/ray/surface/Sphere.java";

    /** The files the zip must hold, in order: the assignment's tasks' files, as the table of tasks lists them. */
    private static List<String> assignmentsFiles() {
        List<String> files = new ArrayList<>();
        ray.assignment.Assignment.current().tasks().forEach(t -> files.addAll(t.projectFiles()));
        return files;
    }

    /** The grader takes the assignment's files: exactly those the zip holds, or it would grade a missing one as the stub. */
    @Test
    public void theGraderTakesTheAssignmentsFiles() {
        assertEquals(StudentFiles.in(PROJECT).keySet(), new java.util.TreeSet<>(assignmentsFiles()));
    }

    @Test(timeout = 900_000)
    @SuppressWarnings("unchecked")
    public void theSolutionsZipHoldsTheFilesWithTheirChecksumsAndGetsFullMarks() throws Exception {
        Path handout = handoutWithSolution("solved");
        Run run = gradle(handout, "submission");
        assertEquals(run.output, 0, run.status);
        Path zip = handout.resolve("build/submission.zip");

        Map<String, byte[]> entries = read(zip);
        List<String> expected = new ArrayList<>(assignmentsFiles());
        expected.add("MANIFEST.sha256");
        assertEquals(expected, new ArrayList<>(entries.keySet()));
        StringBuilder manifest = new StringBuilder();
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            byte[] solution = Files.readAllBytes(PROJECT.resolve(file));
            assertTrue(file + " in the zip is not the file in the project", java.util.Arrays.equals(solution, entries.get(file)));
            String sha256 = sha256(solution);
            manifest.append(sha256).append("  ").append(file).append('\n');
            // What it printed: each file, its size and the start of its checksum.
            assertTrue(run.output, run.output.lines().anyMatch(line -> line.contains(file) && line.contains(" " + solution.length + " bytes")
                    && line.contains(sha256.substring(0, 12)) && !line.contains(sha256.substring(0, 13))));
        }
        assertEquals(manifest.toString().lines().sorted().collect(Collectors.toList()),
                new String(entries.get("MANIFEST.sha256"), StandardCharsets.UTF_8).lines().sorted().collect(Collectors.toList()));
        assertTrue(run.output, run.output.contains("Wrote " + zip.toRealPath()) || run.output.contains("Wrote " + zip.toAbsolutePath()));
        assertTrue(run.output, run.output.lines().anyMatch(line -> line.startsWith("To hand in:") && line.contains("Gradescope")
                && line.contains("PrairieLearn")));

        // The instructor's grader takes the zip as it is: full marks, every bonus point, and the checksums confirmed.
        Path out = FOLDER.getRoot().toPath().resolve("grade-solved");
        int status = new CommandLine(new Grader()).execute("--project", PROJECT.toString(), "--classpath", LIBRARIES,
                "--submission", zip.toString(), "--out", out.toString());
        assertEquals(0, status);
        Map<String, Object> results = new Gson().fromJson(Files.readString(out.resolve("results.json"), StandardCharsets.UTF_8), Map.class);
        List<Map<String, Object>> tests = (List<Map<String, Object>>) results.get("tests");
        assertTrue("too few graded tests: " + tests.size(), tests.size() > 50);
        double possible = 0;
        for (Map<String, Object> t : tests) {
            assertEquals(t.get("name") + ": " + t.get("output"), "passed", t.get("status"));
            possible += (Double) t.get("max_score");
        }
        assertEquals(possible, (Double) results.get("score"), 1e-9);
        String output = (String) results.get("output");
        assertTrue(output, output.contains("MANIFEST.sha256: each of the 8 graded files is the one gradle submission packed"));
        assertFalse("the manifest must not read as a stray file: " + output, output.contains("Ignored"));
        assertFalse(output, output.contains("Not found in the submission"));
    }

    @Test(timeout = 600_000)
    public void aFileThatDoesNotCompileIsRefusedInOneLineAndLeavesNoZip() throws Exception {
        Path handout = handoutWithSolution("broken");
        // An earlier run's zip: it must not survive the refusal, or it would be uploaded by mistake.
        Path zip = handout.resolve("build/submission.zip");
        Files.createDirectories(zip.getParent());
        Files.writeString(zip, "an earlier zip");
        List<String> lines = new ArrayList<>(Files.readAllLines(handout.resolve(SPHERE), StandardCharsets.UTF_8));
        int line = lines.indexOf("        double halfB = f.dot(d);");
        assertTrue("the solution's Sphere.java has no line 'double halfB = f.dot(d);' to break", line >= 0);
        lines.set(line, "        double halfB = f.dot(d)");
        Files.write(handout.resolve(SPHERE), lines, StandardCharsets.UTF_8);

        Run run = gradle(handout, "submission");
        assertNotEquals(run.output, 0, run.status);
        List<String> refusals = run.output.lines().filter(l -> l.contains("Not zipped")).collect(Collectors.toList());
        assertEquals(run.output, 1, refusals.size());
        assertTrue(run.output, refusals.get(0).endsWith("Not zipped: " + SPHERE + ":" + (line + 1) + " does not compile: ';' expected"));
        assertFalse("a refused run leaves the earlier zip behind", Files.exists(zip));
        try (Stream<Path> left = Files.list(zip.getParent())) {
            assertEquals("a refused run leaves nothing in build/", List.of(), left.map(p -> p.getFileName().toString())
                    .filter(name -> name.contains("submission")).collect(Collectors.toList()));
        }
    }

    /** A handout built from this project, with the solution's student files in place of the stubs. */
    private static Path handoutWithSolution(String name) throws IOException {
        Path handout = FOLDER.getRoot().toPath().resolve(name).resolve("ray1");
        Handout.build(PROJECT, handout);
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            Files.copy(PROJECT.resolve(file), handout.resolve(file), StandardCopyOption.REPLACE_EXISTING);
        }
        return handout;
    }

    private static Map<String, byte[]> read(Path zip) throws IOException {
        Map<String, byte[]> entries = new LinkedHashMap<>();
        try (InputStream in = Files.newInputStream(zip); ZipInputStream z = new ZipInputStream(in)) {
            for (ZipEntry e = z.getNextEntry(); e != null; e = z.getNextEntry()) {
                entries.put(e.getName(), z.readAllBytes());
            }
        }
        return entries;
    }

    private static String sha256(byte[] bytes) throws Exception {
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
    }

    private record Run(int status, String output) {
    }

    /**
     * Runs Gradle's {@code task} in {@code project}, offline (the libraries are in Gradle's cache: this
     * build resolved them), with a daemon that stops a minute after its last build, so the test's runs
     * share one and it does not outlive them long.
     */
    private static Run gradle(Path project, String task) throws Exception {
        String home = System.getProperty("ray1.gradleHome");
        boolean windows = System.getProperty("os.name").toLowerCase(java.util.Locale.ROOT).contains("windows");
        String gradle = home == null ? "gradle" : Path.of(home, "bin", windows ? "gradle.bat" : "gradle").toString();
        Path log = project.resolve("..").resolve(task + ".log");
        ProcessBuilder builder = new ProcessBuilder(gradle, "-q", "--offline", "--console=plain",
                "-Dorg.gradle.daemon.idletimeout=60000", task).directory(project.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        builder.environment().put("JAVA_HOME", System.getProperty("ray1.gradleJavaHome", System.getProperty("java.home")));
        Process process = builder.start();
        if (!process.waitFor(5, TimeUnit.MINUTES)) {
            process.destroyForcibly();
            throw new AssertionError("gradle " + task + " took more than 5 minutes in " + project);
        }
        return new Run(process.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
    }
}
