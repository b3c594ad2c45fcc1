package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import com.google.gson.Gson;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.UnaryOperator;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;

/**
 * Submissions that attack the grader, graded as the platforms grade them (as root, with student code
 * as {@value Sandbox#USER}): each gets its right score, a valid results.json within the size limit,
 * no leak, within the time bound. Each case adds a row to build/adversarial/summary.txt (submission,
 * score, bytes, leak, seconds) for the record.
 *
 * <p>The grading tree is a private copy of the project (a folder only root may enter), as on the
 * platforms, where run_autograder and the Dockerfile make the grader's files root's alone.
 */
public class AdversarialSubmissionsTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path CHECKOUT = Path.of(".").toAbsolutePath().normalize();
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));
    private static final String SPHERE = "src/main/java/ray/surface/Sphere.java";
    /** Where the sphere's intersect starts its own work (after the TODO comments). */
    private static final String INTERSECT_BODY = "Vec3 f = ray.origin.minus(center);\n";
    private static final String CLASS_BODY = "public class Sphere extends SphereShape {\n";
    private static final Path SUMMARY = CHECKOUT.resolve("build/adversarial/summary.txt");

    private static Path project;

    @BeforeClass
    public static void privateGradingTree() throws Exception {
        assumeTrue("grading isolation needs root and the user " + Sandbox.USER + " (.ci/run and setup.sh make it)",
                Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent());
        Path root = FOLDER.getRoot().toPath();
        Files.setPosixFilePermissions(root, PosixFilePermissions.fromString("rwx------"));
        project = root.resolve("ray1");
        ProjectTree.copy(CHECKOUT, project, Map.of());
    }

    /** The graded results and what grading them took. */
    private static final class Graded {
        Map<String, Object> results;
        String json;
        long bytes;
        double seconds;
        Path resultsFile;
    }

    /**
     * A static initializer starts a detached process (its own session, so not the test JVM's child)
     * that writes a score of 999 into the platform's results file, at once and every 0.2 s after:
     * the first writes fail (the student's user cannot write there), and the process is ended before
     * the grader writes its own results, which stay the grader's.
     */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void aDetachedProcessCannotReplaceTheResults() throws Exception {
        Path platformResults = FOLDER.getRoot().toPath().resolve("platform/results/results.json");
        Files.createDirectories(platformResults.getParent());
        String fake = "{\"score\": 999.0, \"tests\": []}";
        String loop = "while true; do echo '" + fake + "' > " + platformResults + "; echo '" + fake + "' > "
                + platformResults.getParent().resolve("extra.json") + "; sleep 0.2; done";
        Graded graded = grade("fake-results", Map.of(SPHERE, source -> insertAfter(source, CLASS_BODY,
                "    static {\n        try {\n            new ProcessBuilder(\"setsid\", \"bash\", \"-c\", \"" + loop.replace("\"", "\\\"")
                        + "\").redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();\n"
                        + "        } catch (java.io.IOException e) {\n            throw new java.io.UncheckedIOException(e);\n        }\n    }\n")),
                platformResults);
        // Anything still running would overwrite the file within this wait.
        Thread.sleep(1500);
        String after = Files.readString(platformResults, StandardCharsets.UTF_8);
        assertEquals("the platform's results.json is the grader's", graded.json, after);
        assertFalse(Files.exists(platformResults.getParent().resolve("extra.json")));
        double score = ((Number) graded.results.get("score")).doubleValue();
        assertNotEquals(999.0, score, 0);
        double sum = ((List<Map<String, Object>>) graded.results.get("tests")).stream()
                .mapToDouble(t -> ((Number) t.get("score")).doubleValue()).sum();
        assertEquals("the score is the tests' points", sum, score, 1e-9);
        assertTrue("every test passes: the sphere is the solution",
                passing((List<Map<String, Object>>) graded.results.get("tests"), name -> true) == Boolean.TRUE);
        assertEquals("no process of the student's user is left", 0, studentProcesses());
        record("detached process writes a fake results.json", graded, "no");
    }

    /**
     * A sphere that, before its first test, looks for the hidden tests and the solution everywhere
     * it might find them (the working folder, the class path, the temporary folder, the platforms'
     * folders, every path on any process's command line, the class loaders as resources and through
     * reflection) and then throws what it found, a slice per test, in plain text, base64, reversed
     * base64 and hex. It finds nothing to throw, and the results carry no 64-byte window of any
     * hidden file or solution block in any of those encodings.
     */
    @Test(timeout = 600_000)
    public void aSubmissionThatWalksTheDiskLeaksNothing() throws Exception {
        String probe = Files.readString(CHECKOUT.resolve("src/instructorTest/adversarial/LeakProbe.java.txt"),
                StandardCharsets.UTF_8);
        Graded graded = grade("leak", Map.of(SPHERE, source -> insertAfter(insertAfter(source, CLASS_BODY, probe), INTERSECT_BODY,
                "        if (f != null) {\n            throw new IllegalStateException(leakProbeNext());\n        }\n")), null);
        String report = graded.json.contains("leak-probe: ") ? graded.json.split("leak-probe: ")[1].split("\\\\n")[0] : "(none)";
        // Nothing on disk; what the class loaders give (the explorer's page, say) is no secret, as the finder checks below.
        assertTrue("what the probe found: " + report, report.startsWith("found 0 files, "));
        LeakFinder finder = LeakFinder.of(project);
        assertTrue(finder.secretBytes() > 50_000);
        List<String> leaks = new ArrayList<>();
        collectStrings(graded.results, text -> {
            String how = finder.leakIn(text);
            if (how != null) {
                leaks.add(how + ": " + text.substring(0, Math.min(200, text.length())));
            }
        });
        assertEquals("leaks: " + leaks, List.of(), leaks);
        record("disk walk, leak in plain/base64/reversed/hex", graded, "no");
    }

    /** The finder itself finds a hidden test in each encoding the probe uses, and nothing in an ordinary message. */
    @Test
    public void theLeakFinderFindsEachEncoding() throws Exception {
        LeakFinder finder = LeakFinder.of(project);
        byte[] hidden = Files.readAllBytes(project.resolve("src/instructorTest/java/ray/hidden/Task2HiddenTest.java"));
        byte[] slice = java.util.Arrays.copyOfRange(hidden, 1001, 1400);
        String base64 = java.util.Base64.getEncoder().encodeToString(slice);
        StringBuilder hex = new StringBuilder();
        for (byte b : slice) {
            hex.append(String.format("%02x", b));
        }
        assertEquals("plain", finder.leakIn("boom: " + new String(slice, StandardCharsets.UTF_8)));
        assertEquals("base64", finder.leakIn("b64:" + base64));
        assertEquals("base64 reversed", finder.leakIn("rev:" + new StringBuilder(base64).reverse()));
        assertEquals("hex", finder.leakIn("hex:" + hex));
        assertNull(finder.leakIn("[Task 2 (Sphere)] expected a hit at t = 4; your intersect returned false"));
    }

    /**
     * A static initializer that allocates until the heap is full: the sphere's tests say it ran out
     * of memory, in the sphere's task, never that a scene file is at fault; every other task keeps
     * its points.
     */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void runningOutOfMemoryInAStaticInitializerIsNamedAsSuch() throws Exception {
        Graded graded = grade("out-of-memory", Map.of(SPHERE, source -> insertAfter(source, CLASS_BODY,
                "    static {\n        hoard();\n    }\n\n    private static void hoard() {\n"
                        + "        java.util.List<long[]> all = new java.util.ArrayList<>();\n"
                        + "        while (all.size() >= 0) {\n            all.add(new long[1 << 20]);\n        }\n    }\n")), null);
        List<Map<String, Object>> tests = (List<Map<String, Object>>) graded.results.get("tests");
        List<String> sphereMessages = tests.stream().filter(t -> ((String) t.get("name")).startsWith("Task 2 "))
                .map(t -> (String) t.get("output")).collect(Collectors.toList());
        assertTrue(sphereMessages.stream().anyMatch(m -> m.contains("your code ran out of memory (java.lang.OutOfMemoryError")));
        for (String message : sphereMessages) {
            assertTrue(message, message.contains("ran out of memory") || message.contains("its static initializer failed"));
            assertFalse(message, message.contains("scene file") || message.contains("does not load"));
        }
        assertTrue("the other tasks pass", passing(tests, name -> !name.startsWith("Task 2 ")) == Boolean.TRUE);
        record("static initializer fills the heap", graded, "no");
    }

    /** A loop that never ends in intersect: the sphere's tests fail, every other task keeps its points, in under 2 minutes. */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void anInfiniteLoopCostsOnlyItsTaskAndLittleTime() throws Exception {
        Graded graded = grade("infinite-loop", Map.of(SPHERE, source -> insertAfter(source, INTERSECT_BODY,
                "        while (f != null) {\n            f = f.plus(f.times(0));\n        }\n")), null);
        List<Map<String, Object>> tests = (List<Map<String, Object>>) graded.results.get("tests");
        assertTrue("the sphere's tests fail", passing(tests, name -> name.startsWith("Task 2 ")) == Boolean.FALSE);
        assertTrue("the other tasks pass", passing(tests, name -> !name.startsWith("Task 2 ")) == Boolean.TRUE);
        withinAndClean(graded, 120, "infinite loop in intersect");
    }

    /**
     * Every student class loops forever in its static initializer, so every task's code never
     * finishes: the worst case a submission can make without slowing each test just under its limit
     * (which the time limit bounds). It is graded, 0 points, well within PrairieLearn's 150 s.
     */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void codeThatNeverFinishesInAnyTaskIsGradedWithinThePlatformsLimits() throws Exception {
        Map<String, UnaryOperator<String>> edits = new java.util.LinkedHashMap<>();
        for (String file : StudentFiles.in(project).keySet()) {
            edits.put(file, AdversarialSubmissionsTest::loopingStaticInitializer);
        }
        Graded graded = grade("every-task-loops", edits, null);
        List<Map<String, Object>> tests = (List<Map<String, Object>>) graded.results.get("tests");
        assertTrue("every test fails", passing(tests, name -> true) == Boolean.FALSE);
        assertEquals(0.0, ((Number) graded.results.get("score")).doubleValue(), 0);
        withinAndClean(graded, 150, "every task loops in a static initializer");
    }

    /** A sphere that prints 50 MB and throws 5 MB messages: results.json stays under 1 MB and the other tasks pass. */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void hugeOutputKeepsTheResultsSmall() throws Exception {
        Graded graded = grade("huge-output", Map.of(SPHERE, source -> insertAfter(source, INTERSECT_BODY,
                "        if (f != null) {\n            String shout = \"shout \".repeat(900_000);\n"
                        + "            for (int i = 0; i < 10; i++) {\n                System.out.print(shout);\n            }\n"
                        + "            throw new IllegalStateException(shout);\n        }\n")), null);
        List<Map<String, Object>> tests = (List<Map<String, Object>>) graded.results.get("tests");
        assertTrue("the other tasks pass", passing(tests, name -> !name.startsWith("Task 2 ")) == Boolean.TRUE);
        record("prints 50 MB, throws 5 MB messages", graded, "no");
    }

    /**
     * The whole grade stops at --time-limit: the test then running and every later one fail with the
     * reason, the points earned before count, and results.json is written soon after the limit.
     */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void aWholeGradeStopsAtItsTimeLimitWithThePointsEarnedSoFar() throws Exception {
        // Tasks 2 to 6 never finish, each costing at least its first test's 10 s: the limit comes in Task 3 or 4.
        int limit = 25;
        Map<String, UnaryOperator<String>> edits = new java.util.LinkedHashMap<>();
        for (Map.Entry<String, Integer> file : StudentFiles.in(project).entrySet()) {
            if (file.getValue() > 1) {
                edits.put(file.getKey(), AdversarialSubmissionsTest::loopingStaticInitializer);
            }
        }
        Graded graded = grade("time-limit", edits, null, "--time-limit", String.valueOf(limit));
        List<Map<String, Object>> tests = (List<Map<String, Object>>) graded.results.get("tests");
        List<Map<String, Object>> stopped = tests.stream().filter(t -> ((String) t.get("output")).contains("grading stopped at its time limit"))
                .collect(Collectors.toList());
        assertTrue("the last task's tests are stopped", stopped.stream().anyMatch(t -> ((String) t.get("name")).startsWith("Task 6 ")));
        for (Map<String, Object> t : stopped) {
            assertEquals(t.get("name") + " earns nothing", 0.0, ((Number) t.get("score")).doubleValue(), 0);
        }
        double earned = tests.stream().mapToDouble(t -> ((Number) t.get("score")).doubleValue()).sum();
        assertEquals(earned, ((Number) graded.results.get("score")).doubleValue(), 1e-9);
        assertTrue("points earned before the limit count", earned > 0);
        for (int task = 1; task <= 6; task++) {
            String prefix = "Task " + task + " ";
            assertTrue("task " + task + "'s tests are listed", tests.stream().anyMatch(t -> ((String) t.get("name")).startsWith(prefix)));
        }
        assertTrue(graded.seconds + " s", graded.seconds < limit + 20);
        record("tasks 2-6 never finish, 25 s time limit", graded, "no");
    }

    private static Graded grade(String name, Map<String, UnaryOperator<String>> edits, Path platformResults, String... options)
            throws Exception {
        Path submission = FOLDER.getRoot().toPath().resolve("submission-" + name);
        Files.createDirectories(submission);
        for (String file : StudentFiles.in(project).keySet()) {
            String source = Files.readString(project.resolve(file), StandardCharsets.UTF_8);
            source = edits.getOrDefault(file, UnaryOperator.identity()).apply(source);
            Files.writeString(submission.resolve(Path.of(file).getFileName().toString()), source, StandardCharsets.UTF_8);
        }
        Path out = FOLDER.getRoot().toPath().resolve("grade-" + name);
        List<String> args = new ArrayList<>(List.of("--project", project.toString(), "--classpath", LIBRARIES,
                "--submission", submission.toString(), "--out", out.toString()));
        if (platformResults != null) {
            args.addAll(List.of("--results", platformResults.toString()));
        }
        args.addAll(List.of(options));
        long start = System.nanoTime();
        assertEquals(0, new CommandLine(new Grader()).execute(args.toArray(new String[0])));
        Graded graded = new Graded();
        graded.seconds = (System.nanoTime() - start) / 1e9;
        graded.resultsFile = out.resolve("results.json");
        graded.json = Files.readString(graded.resultsFile, StandardCharsets.UTF_8);
        graded.bytes = Files.size(graded.resultsFile);
        graded.results = readJson(graded.json);
        // Kept beside the summary, to read what each attack got.
        Files.createDirectories(SUMMARY.getParent());
        Files.writeString(SUMMARY.resolveSibling(name + "-results.json"), graded.json, StandardCharsets.UTF_8);
        assertTrue(graded.bytes + " bytes", graded.bytes <= OutputLimits.RESULTS_BYTES);
        return graded;
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> readJson(String json) {
        return new Gson().fromJson(json, Map.class);
    }

    @SuppressWarnings("unchecked")
    private static void collectStrings(Object value, java.util.function.Consumer<String> each) {
        if (value instanceof String) {
            each.accept((String) value);
        } else if (value instanceof Map) {
            ((Map<String, Object>) value).forEach((k, v) -> {
                each.accept(k);
                collectStrings(v, each);
            });
        } else if (value instanceof List) {
            ((List<Object>) value).forEach(v -> collectStrings(v, each));
        }
    }

    private static long studentProcesses() {
        return ProcessHandle.allProcesses().filter(p -> p.info().user().map(Sandbox.USER::equals).orElse(false)).count();
    }

    /** Graded within {@code seconds}, with no process of the student's user left; recorded as {@code submission}. */
    private static void withinAndClean(Graded graded, double seconds, String submission) throws Exception {
        assertTrue(graded.seconds + " s", graded.seconds < seconds);
        assertEquals("no process of the student's user is left", 0, studentProcesses());
        record(submission, graded, "no");
    }

    /** TRUE when every test named so passes, FALSE when none does, null when some do. */
    private static Boolean passing(List<Map<String, Object>> tests, java.util.function.Predicate<String> named) {
        List<Boolean> passed = tests.stream().filter(t -> named.test((String) t.get("name"))).map(t -> "passed".equals(t.get("status")))
                .distinct().collect(Collectors.toList());
        return passed.size() == 1 ? passed.get(0) : null;
    }

    /** The class with a static initializer that never ends. */
    private static String loopingStaticInitializer(String source) {
        return source.replaceFirst("(public class [^{]*\\{\n)",
                "$1    static {\n        while (System.nanoTime() != 0) {\n            Thread.onSpinWait();\n        }\n    }\n");
    }

    private static String insertAfter(String source, String anchor, String inserted) {
        int at = source.indexOf(anchor);
        assertTrue("anchor not found: " + anchor, at >= 0);
        return source.substring(0, at + anchor.length()) + inserted + source.substring(at + anchor.length());
    }

    private static synchronized void record(String submission, Graded graded, String leak) throws Exception {
        Files.createDirectories(SUMMARY.getParent());
        String line = String.format("%-48s score %6.1f  %8d bytes  leak %-3s  %6.1f s%n", submission,
                ((Number) graded.results.get("score")).doubleValue(), graded.bytes, leak, graded.seconds);
        Files.writeString(SUMMARY, line, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    }
}
