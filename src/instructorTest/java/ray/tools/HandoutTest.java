package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.CompileResult;
import ray.grading.ProjectCompiler;
import ray.grading.SolutionMarkers;
import ray.grading.StudentFiles;
import ray.grading.TestOutcome;
import ray.grading.TestProcess;

/**
 * The handout, built and used as a student would: nothing of the solution leaks, nothing
 * instructor-only ships, it compiles on its own, exactly the graded (student) tests fail on the
 * stubs, and with the solution files put back every test passes.
 */
public class HandoutTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    private static Path handout;
    private static List<String> files;
    /** The libraries only: the handout must compile without any instructor class on the classpath. */
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));

    @BeforeClass
    public static void buildHandout() throws Exception {
        handout = FOLDER.getRoot().toPath().resolve("ray1");
        files = Handout.build(PROJECT, handout);
    }

    @Test
    public void shipsTheProjectButNothingInstructorOnly() {
        for (String required : List.of("build.gradle", "settings.gradle", "gradle/legacy-run.gradle", "README.md",
                "src/main/java/ray/surface/Sphere.java", "src/test/java/ray/testing/StudentTaskRule.java",
                "docs/scene-format.md", "scenes/one-sphere.xml", "scenes/reference/one-sphere.png")) {
            assertTrue("the handout lacks " + required, files.contains(required));
        }
        for (String file : files) {
            assertFalse(file, file.startsWith("src/instructor") || file.startsWith(".ci/") || file.startsWith("build/")
                    || file.equals("gradle/instructor.gradle") || file.equals("docs/instructor.md"));
            // Students never run a benchmark (the JMH ones, the Mitsuba 3 comparison): none ships.
            assertFalse("a benchmark ships in the handout: " + file, file.startsWith("src/") && file.toLowerCase().contains("bench"));
        }
    }

    /**
     * A student with only a JDK runs ./gradlew (gradlew on Windows): the wrapper ships in the folder
     * and in the zip, gradlew executable in both (the zip records its Unix mode), pinned to a Gradle 9
     * release with the distribution's SHA-256, and the scripts' line endings are kept by .gitattributes.
     */
    @Test
    public void theWrapperShipsExecutableAndPinnedToAGradle9ReleaseWithItsChecksum() throws Exception {
        for (String required : List.of("gradlew", "gradlew.bat", "gradle/wrapper/gradle-wrapper.jar",
                "gradle/wrapper/gradle-wrapper.properties", ".gitattributes")) {
            assertTrue("the handout lacks " + required, files.contains(required));
        }
        assertTrue("gradlew is not executable in the handout folder", Files.isExecutable(handout.resolve("gradlew")));
        java.util.Properties wrapper = new java.util.Properties();
        try (var in = Files.newInputStream(handout.resolve("gradle/wrapper/gradle-wrapper.properties"))) {
            wrapper.load(in);
        }
        assertTrue(wrapper.getProperty("distributionUrl"),
                wrapper.getProperty("distributionUrl").matches("https://services\\.gradle\\.org/distributions/gradle-9\\.\\d+(\\.\\d+)?-bin\\.zip"));
        assertTrue(wrapper.getProperty("distributionSha256Sum"), String.valueOf(wrapper.getProperty("distributionSha256Sum")).matches("[0-9a-f]{64}"));
        String attributes = Files.readString(handout.resolve(".gitattributes"), StandardCharsets.UTF_8);
        assertTrue(attributes, attributes.contains("gradlew text eol=lf") && attributes.contains("*.bat text eol=crlf"));
        assertTrue("gradlew.bat lost its CRLF line endings", Files.readString(handout.resolve("gradlew.bat"), StandardCharsets.UTF_8).contains("\r\n"));

        Path zip = FOLDER.getRoot().toPath().resolve("ray1-handout.zip");
        Handout.zip(handout, zip);
        Map<String, Integer> modes = new java.util.HashMap<>();
        try (org.apache.commons.compress.archivers.zip.ZipFile archive = org.apache.commons.compress.archivers.zip.ZipFile.builder()
                .setPath(zip).get()) {
            archive.getEntries().asIterator().forEachRemaining(e -> modes.put(e.getName(), e.getUnixMode()));
        }
        assertEquals("gradlew's mode in the zip", Integer.valueOf(0755), modes.get("ray1/gradlew"));
        assertEquals("a scene's mode in the zip", Integer.valueOf(0644), modes.get("ray1/scenes/one-sphere.xml"));
        assertTrue(modes.containsKey("ray1/gradle/wrapper/gradle-wrapper.jar") && modes.containsKey("ray1/gradlew.bat"));
    }

    @Test
    public void theBuildAndReadmeLoseTheirInstructorSections() throws Exception {
        String build = Files.readString(handout.resolve("build.gradle"), StandardCharsets.UTF_8);
        assertFalse("the handout's build.gradle still applies the instructor's build", build.contains("instructor.gradle"));
        assertTrue("the handout's build.gradle lost its test set-up", build.contains("reportTestsByTask(it, 'Tests'"));
        String report = Files.readString(handout.resolve("gradle/test-report.gradle"), StandardCharsets.UTF_8);
        assertTrue("the handout's test report lost its closing line",
                report.contains("${closingWord}: ${passed} passed, ${failed} failed, ${skipped} skipped"));
        String readme = Files.readString(handout.resolve("README.md"), StandardCharsets.UTF_8);
        assertFalse("the handout's README still has the instructor's commands", readme.contains("gradle handout"));
        assertTrue("the handout's README lost the student's commands", readme.contains("gradle test"));
    }

    @Test
    public void instructorSectionsAreCutLineByLine() {
        String text = "keep 1\n// BEGIN INSTRUCTOR\nsecret\n// END INSTRUCTOR\nkeep 2\n<!-- BEGIN INSTRUCTOR -->\nx\n<!-- END INSTRUCTOR -->\n";
        assertEquals("keep 1\nkeep 2\n", Handout.withoutInstructorSections(text, "f"));
        try {
            Handout.withoutInstructorSections("a\n// BEGIN INSTRUCTOR\nb\n", "build.gradle");
            org.junit.Assert.fail("an unended section must be refused");
        } catch (IllegalArgumentException e) {
            assertEquals("build.gradle:2: BEGIN INSTRUCTOR is never ended", e.getMessage());
        }
    }

    /**
     * Every line of a chosen task's solution block that appears nowhere else in the shipped sources
     * must be absent from the handout. A task the assignment leaves out ships solved on purpose: its
     * files are shipped sources like the framework's.
     */
    @Test
    public void noLineOfAnySolutionLeaks() throws Exception {
        Set<String> solutionLines = new HashSet<>();
        Set<String> otherLines = new HashSet<>();
        Set<String> shippedSolved = new HashSet<>();
        ray.assignment.Assignment assignment = ray.assignment.Assignment.current();
        for (ray.assignment.Task task : assignment.table().all()) {
            if (assignment.number(task.id()) == 0) {
                shippedSolved.addAll(task.projectFiles());
            }
        }
        for (String file : files) {
            if (!file.endsWith(".java")) {
                continue;
            }
            boolean solved = shippedSolved.contains(file);
            boolean inSolution = false;
            for (String line : Files.readAllLines(PROJECT.resolve(file), StandardCharsets.UTF_8)) {
                String t = line.strip();
                if (t.equals(SolutionMarkers.BEGIN) || t.equals(SolutionMarkers.END)) {
                    inSolution = t.equals(SolutionMarkers.BEGIN);
                } else if (!t.isEmpty()) {
                    (inSolution && !solved ? solutionLines : otherLines).add(t);
                }
            }
        }
        solutionLines.removeAll(otherLines);
        assertTrue("too few solution lines found to make this check mean anything", solutionLines.size() > 40);
        for (String file : files) {
            if (file.endsWith(".java") || file.endsWith(".md") || file.endsWith(".gradle") || file.endsWith(".xml")) {
                for (String line : Files.readAllLines(handout.resolve(file), StandardCharsets.UTF_8)) {
                    assertFalse(file + " leaks a solution line: " + line.strip(), solutionLines.contains(line.strip()));
                }
            }
        }
    }

    @Test(timeout = 300_000)
    public void onTheStubsExactlyTheStudentTestsFailAndWithTheSolutionAllPass() throws Exception {
        List<TestOutcome> onStubs = compileAndRunEverything(handout, "stubs");
        List<TestOutcome> graded = onStubs.stream().filter(t -> t.task() > 0).collect(Collectors.toList());
        List<TestOutcome> ungraded = onStubs.stream().filter(t -> t.task() == 0).collect(Collectors.toList());
        assertTrue("the handout has no graded tests", graded.size() > 40);
        // The framework's own tests stay in the instructor's build: a student runs only tests of their work.
        assertEquals("tests in the handout that judge no task", List.of(),
                ungraded.stream().map(TestOutcome::id).collect(Collectors.toList()));
        for (TestOutcome t : graded) {
            assertFalse(t.id() + " passes on the stubs: a student would get its points for nothing", t.passed());
            assertTrue(t.id() + "'s failure does not say what to do: " + t.message(), t.message().contains("TODO(Task " + t.task() + ")"));
        }
        for (int task = 1; task <= 4; task++) {
            int n = task;
            assertTrue("no graded test for task " + task, graded.stream().anyMatch(t -> t.task() == n));
        }

        Path solved = FOLDER.getRoot().toPath().resolve("solved");
        Handout.build(PROJECT, solved);
        for (String studentFile : StudentFiles.in(PROJECT).keySet()) {
            Files.copy(PROJECT.resolve(studentFile), solved.resolve(studentFile), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        List<TestOutcome> withSolution = compileAndRunEverything(solved, "solved");
        assertEquals(onStubs.size(), withSolution.size());
        for (TestOutcome t : withSolution) {
            assertTrue(t.id() + " fails with the solution in place: " + t.message(), t.passed());
        }
    }

    private static List<TestOutcome> compileAndRunEverything(Path tree, String name) throws Exception {
        CompileResult compiled = ProjectCompiler.compile(tree, tree.resolve("classes"), LIBRARIES);
        assertTrue("the " + name + " handout does not compile on its own:\n" + compiled.messages(), compiled.ok());
        return new TestProcess(tree, tree.resolve("classes"), LIBRARIES, tree.resolve("test-run")).withUngradedTests().run(null);
    }

    @Test
    public void theStudentFilesOfTheHandoutAreTheStubs() throws Exception {
        for (Map.Entry<String, Integer> f : StudentFiles.in(PROJECT).entrySet()) {
            String shipped = Files.readString(handout.resolve(f.getKey()), StandardCharsets.UTF_8);
            ray.assignment.Assignment assignment = ray.assignment.Assignment.current();
            String id = assignment.ofFile(f.getKey()).orElseThrow().id();
            String expected = SolutionMarkers.studentVersion(Files.readString(PROJECT.resolve(f.getKey()), StandardCharsets.UTF_8), f.getKey(),
                    f.getValue(), assignment.hints(id));
            assertEquals(f.getKey(), expected, shipped);
            assertTrue(f.getKey(), shipped.contains("// TODO(Task " + f.getValue() + ")"));
        }
    }
}
