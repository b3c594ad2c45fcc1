package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import com.google.gson.Gson;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import java.util.function.UnaryOperator;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;
import ray.tools.AutograderBundle;
import ray.tools.KitInputs;

/**
 * Submissions that attack the grader, graded as Gradescope grades them: the real bundle, unpacked
 * into a folder laid out like /autograder, its run_autograder run as root, with student code as
 * {@value Sandbox#USER}. Each attack rides on the stub handout (or on the solution, where the attack
 * needs working code to stand out) and must earn exactly what the code's own work earns. After every
 * grading: a valid results.json within the size limit, no 64-byte window of a hidden test, a solution
 * or a solution class in it in any encoding ({@link LeakFinder}), the bundle's files unchanged, and no
 * process of any student user alive. Each case adds a row to build/adversarial/summary.txt
 * (attack, score, bytes, leak, seconds) for the record.
 *
 * <p>The attacks themselves are under src/instructorTest/adversarial: each is inserted into a student
 * class's body, and some throw what they found from intersect, where the results show it.
 */
public class AdversarialSubmissionsTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path CHECKOUT = Path.of(".").toAbsolutePath().normalize();
    private static final String SPHERE = "src/main/java/ray/surface/Sphere.java";
    private static final String GROUP = "src/main/java/ray/surface/Group.java";
    private static final String REPEAT = "src/main/java/ray/shading/RepeatTexture.java";
    /** Where the sphere's intersect starts, in the solution and the stub alike. */
    private static final String INTERSECT = "public boolean intersect(IntersectionRecord out, Ray ray) {\n";
    private static final Path SUMMARY = CHECKOUT.resolve("build/adversarial/summary.txt");

    private static Path bundle;
    private static LeakFinder finder;

    /** Which handed-in files an attack starts from. */
    private enum Base {
        /** The handout's stubs: every test fails, 0 points. */
        STUB,
        /** The solution: every test passes. */
        SOLUTION
    }

    @BeforeClass
    public static void buildTheBundle() throws Exception {
        assumeTrue("grading isolation needs root and the user " + Sandbox.USER + " (.ci/run and setup.sh make it)",
                Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent());
        Files.setPosixFilePermissions(FOLDER.getRoot().toPath(), PosixFilePermissions.fromString("rwx------"));
        bundle = FOLDER.getRoot().toPath().resolve("ray1-gradescope.zip");
        KitInputs kit = new KitInputs();
        AutograderBundle.build(CHECKOUT, bundle, kit.classes, kit.libraries);
        Path unpacked = FOLDER.getRoot().toPath().resolve("bundle-as-shipped");
        KitInputs.unpack(bundle, unpacked);
        finder = LeakFinder.of(unpacked.resolve("ray1"));
        // This run's table only.
        Files.deleteIfExists(SUMMARY);
        // What the stub handout is told, every student may read: a visible test may describe an input as a hidden one does.
        Graded stub = grade("stub", Base.STUB, Map.of());
        collectStrings(visible(stub), finder::know);
    }

    /** The graded results and what grading them took. */
    private static final class Graded {
        Map<String, Object> results;
        List<Map<String, Object>> tests;
        String json;
        long bytes;
        double seconds;
        Path root;

        double score() {
            return ((Number) results.get("score")).doubleValue();
        }

        /** Every test's output, one after another. */
        String outputs() {
            return tests.stream().map(t -> (String) t.get("output")).collect(Collectors.joining("\n"));
        }
    }

    // ---- The attacks of the old design, where student code ran beside the tests ----

    /**
     * Forged results: a thread writes frames of every type (and lines that look like passed tests) to
     * the worker's raw standard output, and passed-test lines into every file it can find named on a
     * command line, as long as the worker runs. The stub still scores nothing, and the grade finishes.
     */
    @Test(timeout = 900_000)
    public void forgedFramesAndForgedFilesEarnNothing() throws Exception {
        Graded graded = grade("forged-frames", Base.STUB, Map.of(SPHERE, probe("ForgeProbe")));
        assertEquals(0, graded.score(), 0);
        assertEquals("every test fails", Boolean.FALSE, passing(graded.tests, name -> true));
        assertClean(graded, LOADED_MACHINE_SECONDS, "forged frames and result files (stub)");
    }

    /**
     * Through sun.misc.Unsafe, student code looks for the test runner, JUnit, the tests and their
     * helpers, and overwrites the static fields of every grading class it can load: it finds none of
     * them (they are in the judge), and breaking its own worker earns nothing.
     */
    @Test(timeout = 900_000)
    public void unsafeFindsNoGradingClassAndEarnsNothing() throws Exception {
        Graded graded = grade("unsafe", Base.STUB, Map.of(SPHERE, both(probe("UnsafeProbe"), throwing("unsafeNext()"))));
        assertTrue(graded.outputs(), graded.outputs().contains("unsafe-probe: found []"));
        assertFalse(graded.outputs(), graded.outputs().matches("(?s).*unsafe-probe: found \\[[^\\]].*"));
        assertEquals(0, graded.score(), 0);
        assertClean(graded, LOADED_MACHINE_SECONDS, "Unsafe on the grader's classes (stub)");
    }

    /**
     * Writable inputs: student code tries to write over, and delete, every scene, mesh, texture,
     * reference, class file and results file it can reach from / and from every command line. It
     * changes none (the judge's are root's, in a folder only root may enter), and earns nothing.
     */
    @Test(timeout = 900_000)
    public void theInputsCannotBeChanged() throws Exception {
        Graded graded = grade("overwrite", Base.STUB, Map.of(SPHERE, both(probe("OverwriteProbe"), throwing("OVERWRITE_REPORT"))));
        assertTrue(graded.outputs(), graded.outputs().matches("(?s).*overwrite-probe: looked at [1-9]\\d* files, changed 0: .*"));
        assertEquals(0, graded.score(), 0);
        assertClean(graded, LOADED_MACHINE_SECONDS, "overwrites every input it finds (stub)");
    }

    /**
     * Shadowed test helpers: a handed-in file that also declares a top-level class named like a test
     * helper (HitAsserts beside the sphere, TextureLookups beside the repeat texture) is refused before
     * anything runs, with a line naming the class; the stub's score stays 0.
     */
    @Test(timeout = 900_000)
    public void aClassNamedLikeATestHelperIsRefused() throws Exception {
        Graded graded = grade("shadowed-helpers", Base.STUB, Map.of(
                SPHERE, source -> source + "\nclass HitAsserts {\n    static void assertHit() {\n    }\n}\n",
                REPEAT, source -> source + "\nclass TextureLookups {\n}\n"));
        assertEquals(0, graded.score(), 0);
        for (Map<String, Object> t : graded.tests) {
            String name = (String) t.get("name");
            String output = (String) t.get("output");
            if (name.startsWith("Task 2 ")) {
                assertTrue(output, output.contains("the class ray.surface.HitAsserts must not be defined there"));
            } else if (name.startsWith("Task 5 ")) {
                assertTrue(output, output.contains("the class ray.shading.TextureLookups must not be defined there"));
            }
        }
        assertClean(graded, LOADED_MACHINE_SECONDS, "top-level classes named like test helpers (stub)");
    }

    /**
     * Processes that outlive their JVM: a detached child in a session of its own that ignores signals,
     * names a folder of its own in RAY1_SANDBOX, stops every process its user may signal and grows a
     * file, plus an orphaned grandchild and a plain sleeper. None is alive after grading, and the
     * stub earns nothing.
     */
    @Test(timeout = 900_000)
    public void processesItStartsEndWithTheGrading() throws Exception {
        Graded graded = grade("lingering-processes", Base.STUB, Map.of(SPHERE, probe("LingerProbe")));
        assertEquals(0, graded.score(), 0);
        assertClean(graded, LOADED_MACHINE_SECONDS, "detached, stopping, signal-proof children (stub)");
    }

    /**
     * A stalled worker: the group's code starts the stopping children above (which stop every process
     * of the student's user, the worker too) and then never returns from intersect. The group's first
     * test ends at its own limit, the worker and its children are ended, the group's later tests are
     * skipped, and every other task keeps its points: the grade ends without its time limit (set to
     * 300 s here, five times what a loaded machine needs, so that the limit stops nothing but a hang).
     */
    @Test(timeout = 900_000)
    public void aStalledWorkerEndsWithinTheTimeLimitWithThePointsEarnedSoFar() throws Exception {
        int limit = 300;
        Graded graded = grade("stalled-worker", Base.SOLUTION, Map.of(GROUP, both(probe("LingerProbe"), source -> insertAfter(source,
                INTERSECT, "        try {\n            Thread.sleep(Long.MAX_VALUE);\n        } catch (InterruptedException e) {\n"
                        + "            Thread.currentThread().interrupt();\n        }\n"))), Map.of("RAY1_TIME_LIMIT", String.valueOf(limit)));
        assertEquals("every task but the group's keeps its points", Boolean.TRUE, passing(graded.tests, name -> !name.startsWith("Task 4 ")));
        double others = graded.tests.stream().filter(t -> !((String) t.get("name")).startsWith("Task 4 "))
                .mapToDouble(t -> ((Number) t.get("max_score")).doubleValue()).sum();
        assertTrue(others > 100);
        assertEquals("only the group's tests lose points", others, graded.score(), 1e-9);
        List<String> groupOutputs = graded.tests.stream().filter(t -> ((String) t.get("name")).startsWith("Task 4 "))
                .map(t -> (String) t.get("output")).collect(Collectors.toList());
        assertTrue(groupOutputs.get(0), groupOutputs.get(0).contains("took longer than 10 s"));
        assertTrue(groupOutputs.stream().skip(1).allMatch(o -> o.contains("skipped: your code did not finish in test")));
        assertFalse("the time limit was not needed", graded.outputs().contains("grading stopped at its time limit"));
        assertClean(graded, limit, "group stalls its worker, stops processes (solution)");
    }

    /**
     * Secrets in memory: student code reads its own JVM's memory (and every other process's it may)
     * for class files and test sources, and throws what it kept, gzipped, in base64. It reads class
     * files (the framework's, its own), none of them secret: the hidden tests, the tests and the other
     * tasks' solutions are never in its JVM.
     */
    @Test(timeout = 900_000)
    public void itsMemoryHoldsNoSecret() throws Exception {
        Graded graded = grade("memory", Base.STUB, Map.of(SPHERE, both(probe("MemoryProbe"), throwing("memoryNext()"))));
        java.util.regex.Matcher found = java.util.regex.Pattern.compile("memory-probe: (\\d+) class files").matcher(graded.outputs());
        assertTrue(graded.outputs(), found.find());
        assertTrue("it read class files out of its memory: " + found.group(), Integer.parseInt(found.group(1)) > 0);
        assertEquals(0, graded.score(), 0);
        assertClean(graded, LOADED_MACHINE_SECONDS, "reads /proc/self/mem for classes, gzip+base64 (stub)");
    }

    /**
     * Across submissions under gradeAll, two at once: a submission between two correct ones writes into
     * every other sandbox folder it can find, kills every process it can see and leaves a process
     * trying again every 0.2 s. The correct ones get every point, it gets the stub's 0, and no process
     * of a student user is left.
     */
    @Test(timeout = 900_000)
    public void aSubmissionCannotReachTheOnesGradedBesideIt() throws Exception {
        Path dir = FOLDER.getRoot().toPath().resolve("class-with-attacker");
        writeSubmission(dir.resolve("submission_a"), Base.SOLUTION, Map.of());
        writeSubmission(dir.resolve("submission_b"), Base.STUB, Map.of(SPHERE, probe("CrossProbe")));
        writeSubmission(dir.resolve("submission_c"), Base.SOLUTION, Map.of());
        Path out = FOLDER.getRoot().toPath().resolve("class-grades");
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        GradeAll command = new GradeAll();
        command.log = new PrintStream(log, true, StandardCharsets.UTF_8);
        String libraries = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
                .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));
        long start = System.nanoTime();
        int status = new CommandLine(command).execute("--project", CHECKOUT.toString(), "--classpath", libraries,
                "--submissions", dir.toString(), "--out", out.toString(), "--jobs", "2");
        double seconds = (System.nanoTime() - start) / 1e9;
        assertEquals(log.toString(StandardCharsets.UTF_8), 0, status);
        for (String correct : List.of("submission_a", "submission_c")) {
            GradedResult result = GradedResult.read(out.resolve(correct).resolve("results.json"));
            assertTrue(correct + ": " + result, result.score() >= result.maxScore() && result.maxScore() > 0);
        }
        Graded attacker = read(out.resolve("submission_b").resolve("results.json"));
        attacker.seconds = seconds;
        assertEquals(0, attacker.score(), 0);
        assertEquals("no process of a student user is left", List.of(), studentProcesses());
        record("gradeAll: writes into other sandboxes, kills all (stub)", attacker, "no");
    }

    // ---- Attacks on the limits: time, memory, output, the platform's results file, the disk ----

    /**
     * A static initializer starts a detached process (its own session) that writes a score of 999 into
     * the platform's results file, at once and every 0.2 s after: the writes fail (the student's user
     * cannot write there), the process is ended with the grading, and the results are the grader's.
     */
    @Test(timeout = 900_000)
    public void aDetachedProcessCannotReplaceTheResults() throws Exception {
        Path platformResults = FOLDER.getRoot().toPath().resolve("fake-results/results/results.json");
        String fake = "{\"score\": 999.0, \"tests\": []}";
        String loop = "while true; do echo '" + fake + "' > " + platformResults + "; echo '" + fake + "' > "
                + platformResults.getParent().resolve("extra.json") + "; sleep 0.2; done";
        Graded graded = grade("fake-results", Base.SOLUTION, Map.of(SPHERE, source -> insertAfter(source, CLASS_LINE.apply(source),
                "    static {\n        try {\n            new ProcessBuilder(\"setsid\", \"bash\", \"-c\", \"" + loop.replace("\"", "\\\"")
                        + "\").redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();\n"
                        + "        } catch (java.io.IOException e) {\n            throw new java.io.UncheckedIOException(e);\n        }\n    }\n")));
        // Anything still running would overwrite the file within this wait.
        Thread.sleep(1500);
        assertEquals("the platform's results.json is the grader's", graded.json, Files.readString(platformResults, StandardCharsets.UTF_8));
        assertFalse(Files.exists(platformResults.getParent().resolve("extra.json")));
        assertNotEquals(999.0, graded.score(), 0);
        double sum = graded.tests.stream().mapToDouble(t -> ((Number) t.get("score")).doubleValue()).sum();
        assertEquals("the score is the tests' points", sum, graded.score(), 1e-9);
        assertEquals("every test passes: the sphere is the solution", Boolean.TRUE, passing(graded.tests, name -> true));
        assertClean(graded, LOADED_MACHINE_SECONDS, "detached process writes a fake results.json");
    }

    /**
     * A sphere that, before its first test, looks for the hidden tests and the solution everywhere it
     * might find them (the working folder, the class path, the temporary folder, the platforms'
     * folders, every path on any process's command line, the class loaders as resources and through
     * reflection) and then throws what it found, a slice per test, in plain text, base64, reversed
     * base64 and hex. It finds nothing to throw.
     */
    @Test(timeout = 900_000)
    public void aSubmissionThatWalksTheDiskLeaksNothing() throws Exception {
        Graded graded = grade("leak", Base.SOLUTION, Map.of(SPHERE, both(probe("LeakProbe"), throwing("leakProbeNext()"))));
        String report = graded.json.contains("leak-probe: ") ? graded.json.split("leak-probe: ")[1].split("\\\\n")[0] : "(none)";
        assertTrue("what the probe found: " + report, report.startsWith("found 0 files, "));
        assertClean(graded, LOADED_MACHINE_SECONDS, "disk walk, leak in plain/base64/reversed/hex");
    }

    /** The finder itself finds a hidden test and a solution class in each encoding the probes use, and nothing in an ordinary message. */
    @Test
    public void theLeakFinderFindsEachEncoding() throws Exception {
        byte[] hidden = Files.readAllBytes(CHECKOUT.resolve("src/instructorTest/java/ray/hidden/SphereHiddenTest.java"));
        byte[] slice = java.util.Arrays.copyOfRange(hidden, 1001, 1400);
        String base64 = java.util.Base64.getEncoder().encodeToString(slice);
        assertEquals("plain", finder.leakIn("boom: " + new String(slice, StandardCharsets.UTF_8)));
        assertEquals("base64", finder.leakIn("b64:" + base64));
        assertEquals("base64 reversed", finder.leakIn("rev:" + new StringBuilder(base64).reverse()));
        assertEquals("hex", finder.leakIn("hex:" + HexFormat.of().formatHex(slice)));
        Path solutionClass = FOLDER.getRoot().toPath().resolve("bundle-as-shipped/ray1").resolve(PrecompiledTree.FOLDER)
                .resolve("classes/ray/surface/Triangle.class");
        byte[] code = Files.readAllBytes(solutionClass);
        ByteArrayOutputStream zipped = new ByteArrayOutputStream();
        try (java.util.zip.GZIPOutputStream gzip = new java.util.zip.GZIPOutputStream(zipped)) {
            gzip.write(code);
        }
        assertEquals("gzip base64", finder.leakIn("memory: " + java.util.Base64.getEncoder().encodeToString(zipped.toByteArray())));
        assertNull(finder.leakIn("[Task 2 (Sphere)] expected a hit at t = 4; your intersect returned false"));
        // The handout's own classes are no secret, though the solution's share bytes with them.
        Path stubClass = solutionClass.getParent().getParent().getParent().resolveSibling("handout/ray/surface/Triangle.class");
        assertNull(finder.leakIn(java.util.Base64.getEncoder().encodeToString(Files.readAllBytes(stubClass))));
        // Nor are the JDK's classes, which hold windows of any class file's boilerplate (this one a string
        // concatenation's bootstrap, as a hidden test's does); code that reads its own memory finds them.
        try (java.io.InputStream jdkClass = ClassLoader.getSystemResourceAsStream("java/util/logging/LogManager$LoggerContext.class")) {
            ByteArrayOutputStream jdkZipped = new ByteArrayOutputStream();
            try (java.util.zip.GZIPOutputStream gzip = new java.util.zip.GZIPOutputStream(jdkZipped)) {
                gzip.write(jdkClass.readAllBytes());
            }
            assertNull(finder.leakIn("memory: " + java.util.Base64.getEncoder().encodeToString(jdkZipped.toByteArray())));
        }
    }

    /**
     * A static initializer that allocates until the heap is full: the sphere's tests say it ran out of
     * memory, in the sphere's task, never that a scene file is at fault; every other task keeps its points.
     */
    @Test(timeout = 900_000)
    public void runningOutOfMemoryInAStaticInitializerIsNamedAsSuch() throws Exception {
        Graded graded = grade("out-of-memory", Base.SOLUTION, Map.of(SPHERE, source -> insertAfter(source, CLASS_LINE.apply(source),
                "    static {\n        hoard();\n    }\n\n    private static void hoard() {\n"
                        + "        java.util.List<long[]> all = new java.util.ArrayList<>();\n"
                        + "        while (all.size() >= 0) {\n            all.add(new long[1 << 20]);\n        }\n    }\n")));
        List<String> sphereMessages = graded.tests.stream().filter(t -> ((String) t.get("name")).startsWith("Task 2 "))
                .map(t -> (String) t.get("output")).collect(Collectors.toList());
        assertTrue(sphereMessages.toString(), sphereMessages.stream().anyMatch(m -> m.contains("your code ran out of memory (java.lang.OutOfMemoryError")));
        for (String message : sphereMessages) {
            assertTrue(message, message.contains("ran out of memory") || message.contains("its static initializer failed"));
            assertFalse(message, message.contains("scene file") || message.contains("does not load"));
        }
        assertEquals("the other tasks pass", Boolean.TRUE, passing(graded.tests, name -> !name.startsWith("Task 2 ")));
        assertClean(graded, LOADED_MACHINE_SECONDS, "static initializer fills the heap");
    }

    /**
     * A loop that never ends in intersect: the sphere's tests fail and every other task keeps its
     * points, in little time: its first test's limit, not the whole grade's (about 35 s on a quiet
     * machine; the bound is generous, for a loaded one).
     */
    @Test(timeout = 900_000)
    public void anInfiniteLoopCostsOnlyItsTaskAndLittleTime() throws Exception {
        Graded graded = grade("infinite-loop", Base.SOLUTION, Map.of(SPHERE, source -> insertAfter(source, INTERSECT,
                "        while (ray != null) {\n            Thread.onSpinWait();\n        }\n")));
        assertEquals("the sphere's tests fail", Boolean.FALSE, passing(graded.tests, name -> name.startsWith("Task 2 ")));
        assertEquals("the other tasks pass", Boolean.TRUE, passing(graded.tests, name -> !name.startsWith("Task 2 ")));
        assertFalse("the time limit was not needed", graded.outputs().contains("grading stopped at its time limit"));
        assertClean(graded, LITTLE_TIME_SECONDS, "infinite loop in intersect");
    }

    /**
     * Every student class loops forever in its static initializer, so every task's code never
     * finishes: the worst case a submission can make without slowing each test just under its limit
     * (which the time limit bounds). It is graded, 0 points, well within PrairieLearn's 150 s on a
     * quiet machine (docs/instructor.md has the time); the bound here is generous, for a loaded one.
     */
    @Test(timeout = 900_000)
    public void codeThatNeverFinishesInAnyTaskIsGradedWithinThePlatformsLimits() throws Exception {
        Map<String, UnaryOperator<String>> edits = new LinkedHashMap<>();
        for (String file : StudentFiles.in(CHECKOUT).keySet()) {
            edits.put(file, AdversarialSubmissionsTest::loopingStaticInitializer);
        }
        Graded graded = grade("every-task-loops", Base.SOLUTION, edits);
        assertEquals("every test fails", Boolean.FALSE, passing(graded.tests, name -> true));
        assertEquals(0.0, graded.score(), 0);
        assertFalse("the time limit was not needed", graded.outputs().contains("grading stopped at its time limit"));
        assertClean(graded, LITTLE_TIME_SECONDS, "every task loops in a static initializer");
    }

    /** A sphere that prints 50 MB and throws 5 MB messages: results.json stays under 1 MB and the other tasks pass. */
    @Test(timeout = 900_000)
    public void hugeOutputKeepsTheResultsSmall() throws Exception {
        Graded graded = grade("huge-output", Base.SOLUTION, Map.of(SPHERE, source -> insertAfter(source, INTERSECT,
                "        if (ray != null) {\n            String shout = \"shout \".repeat(900_000);\n"
                        + "            for (int i = 0; i < 10; i++) {\n                System.out.print(shout);\n            }\n"
                        + "            throw new IllegalStateException(shout);\n        }\n")));
        assertEquals("the other tasks pass", Boolean.TRUE, passing(graded.tests, name -> !name.startsWith("Task 2 ")));
        assertClean(graded, LOADED_MACHINE_SECONDS, "prints 50 MB, throws 5 MB messages");
    }

    /**
     * The whole grade stops at its time limit: the test then running and every later one fail with the
     * reason, the points earned before count, and results.json is written soon after the limit.
     */
    @Test(timeout = 900_000)
    public void aWholeGradeStopsAtItsTimeLimitWithThePointsEarnedSoFar() throws Exception {
        // Tasks 2 to 6 never finish, each costing at least its first test's limit: the time limit comes in Task 3 or 4.
        int limit = 25;
        Map<String, UnaryOperator<String>> edits = new LinkedHashMap<>();
        for (Map.Entry<String, Integer> file : StudentFiles.in(CHECKOUT).entrySet()) {
            if (file.getValue() > 1) {
                edits.put(file.getKey(), AdversarialSubmissionsTest::loopingStaticInitializer);
            }
        }
        Graded graded = grade("time-limit", Base.SOLUTION, edits, Map.of("RAY1_TIME_LIMIT", String.valueOf(limit)));
        List<Map<String, Object>> stopped = graded.tests.stream()
                .filter(t -> ((String) t.get("output")).contains("grading stopped at its time limit")).collect(Collectors.toList());
        assertTrue("the last task's tests are stopped", stopped.stream().anyMatch(t -> ((String) t.get("name")).startsWith("Task 6 ")));
        for (Map<String, Object> t : stopped) {
            assertEquals(t.get("name") + " earns nothing", 0.0, ((Number) t.get("score")).doubleValue(), 0);
        }
        double earned = graded.tests.stream().mapToDouble(t -> ((Number) t.get("score")).doubleValue()).sum();
        assertEquals(earned, graded.score(), 1e-9);
        assertTrue("points earned before the limit count", earned > 0);
        for (int task = 1; task <= 6; task++) {
            String prefix = "Task " + task + " ";
            assertTrue("task " + task + "'s tests are listed", graded.tests.stream().anyMatch(t -> ((String) t.get("name")).startsWith(prefix)));
        }
        // Soon after the limit: ending the worker and writing results.json, generously for a loaded machine.
        assertClean(graded, limit + 120, "tasks 2-6 never finish, 25 s time limit");
    }

    /**
     * How long a grading in these tests may take: a bound on hangs, not on speed. A grade takes 15 to
     * 40 s on two quiet cores and up to 130 s while another build keeps them busy; what each attack
     * costs in time on a quiet machine is in the attack table and docs/instructor.md.
     */
    private static final double LOADED_MACHINE_SECONDS = 600;

    /**
     * "Little time" for code that never finishes: well under the 540 s whole-grade limit of the
     * Gradescope bundle these tests run, so that a loop that cost the whole limit fails, with room
     * for a loaded machine (such a grade takes 35 to 80 s on two quiet cores).
     */
    private static final double LITTLE_TIME_SECONDS = 300;

    // ---- Grading through the bundle ----

    private static Graded grade(String name, Base base, Map<String, UnaryOperator<String>> edits) throws Exception {
        return grade(name, base, edits, Map.of());
    }

    /**
     * Unpacks the bundle into a fresh folder laid out like /autograder, hands in the base's files with
     * {@code edits} applied, and runs run_autograder as the platform does, with {@code environment}
     * added; checks the results' size and that the bundle's files are as shipped.
     */
    private static Graded grade(String name, Base base, Map<String, UnaryOperator<String>> edits, Map<String, String> environment)
            throws Exception {
        Path root = FOLDER.getRoot().toPath().resolve(name);
        KitInputs.unpack(bundle, root.resolve("source"));
        writeSubmission(root.resolve("submission"), base, edits);
        String before = fingerprint(root.resolve("source"));
        Map<String, String> variables = new LinkedHashMap<>(environment);
        variables.put("AUTOGRADER_ROOT", root.toString());
        Path log = root.resolve("run.log");
        long start = System.nanoTime();
        assertEquals(0, KitInputs.runScript(root.resolve("source/run_autograder"), variables, log));
        double seconds = (System.nanoTime() - start) / 1e9;
        Graded graded = read(root.resolve("results/results.json"));
        graded.seconds = seconds;
        graded.root = root;
        // Kept beside the summary, to read what each attack got.
        Files.createDirectories(SUMMARY.getParent());
        Files.writeString(SUMMARY.resolveSibling(name + "-results.json"), graded.json, StandardCharsets.UTF_8);
        Files.copy(log, SUMMARY.resolveSibling(name + "-grader.log"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        assertTrue(graded.bytes + " bytes", graded.bytes <= OutputLimits.RESULTS_BYTES);
        assertEquals("the bundle's files are as shipped", before, fingerprint(root.resolve("source")));
        return graded;
    }

    @SuppressWarnings("unchecked")
    private static Graded read(Path resultsFile) throws Exception {
        Graded graded = new Graded();
        graded.json = Files.readString(resultsFile, StandardCharsets.UTF_8);
        graded.bytes = Files.size(resultsFile);
        graded.results = new Gson().fromJson(graded.json, Map.class);
        graded.tests = (List<Map<String, Object>>) graded.results.get("tests");
        return graded;
    }

    /** Writes {@code base}'s student files into {@code folder}, flat as the platforms hand them in, with {@code edits} applied. */
    private static void writeSubmission(Path folder, Base base, Map<String, UnaryOperator<String>> edits) throws Exception {
        Files.createDirectories(folder);
        for (String file : StudentFiles.in(CHECKOUT).keySet()) {
            String source = Files.readString(CHECKOUT.resolve(file), StandardCharsets.UTF_8);
            if (base == Base.STUB) {
                source = SolutionMarkers.studentVersion(source, file);
            }
            source = edits.getOrDefault(file, UnaryOperator.identity()).apply(source);
            Files.writeString(folder.resolve(Path.of(file).getFileName().toString()), source, StandardCharsets.UTF_8);
        }
    }

    /**
     * The SHA-256 of every file's path, owner, owner's permissions and bytes under {@code root}. The
     * group's and others' permissions are left out: run_autograder itself takes them away.
     */
    private static String fingerprint(Path root) throws Exception {
        MessageDigest digest = MessageDigest.getInstance("SHA-256");
        try (Stream<Path> walk = Files.walk(root)) {
            for (Path p : walk.sorted().collect(Collectors.toList())) {
                digest.update(root.relativize(p).toString().getBytes(StandardCharsets.UTF_8));
                digest.update(Files.getOwner(p).getName().getBytes(StandardCharsets.UTF_8));
                digest.update(PosixFilePermissions.toString(Files.getPosixFilePermissions(p)).substring(0, 3).getBytes(StandardCharsets.UTF_8));
                if (Files.isRegularFile(p)) {
                    digest.update(Files.readAllBytes(p));
                }
            }
        }
        return HexFormat.of().formatHex(digest.digest());
    }

    /** The attack in src/instructorTest/adversarial/{@code name}.java.txt, inserted at the start of the class's body. */
    private static UnaryOperator<String> probe(String name) {
        return source -> {
            try {
                String probe = Files.readString(CHECKOUT.resolve("src/instructorTest/adversarial/" + name + ".java.txt"), StandardCharsets.UTF_8);
                // The probes name the sphere's class where they need a class of their own; any student class will do.
                String className = source.replaceFirst("(?s).*public class (\\w+).*", "$1");
                return insertAfter(source, CLASS_LINE.apply(source), probe.replace("Sphere.class", className + ".class"));
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        };
    }

    /** {@code first}, then {@code second}. */
    private static UnaryOperator<String> both(UnaryOperator<String> first, UnaryOperator<String> second) {
        return source -> second.apply(first.apply(source));
    }

    /** Intersect throws {@code message} (a Java expression) as its first statement. */
    private static UnaryOperator<String> throwing(String message) {
        return source -> insertAfter(source, INTERSECT,
                "        if (ray != null) {\n            throw new IllegalStateException(" + message + ");\n        }\n");
    }

    /** The line that opens the public class's body. */
    private static final UnaryOperator<String> CLASS_LINE = source -> source.replaceFirst("(?s).*?(public class [^{]*\\{\n).*", "$1");

    private static String insertAfter(String source, String anchor, String inserted) {
        int at = source.indexOf(anchor);
        assertTrue("anchor not found: " + anchor, at >= 0);
        return source.substring(0, at + anchor.length()) + inserted + source.substring(at + anchor.length());
    }

    /** The class with a static initializer that never ends. */
    private static String loopingStaticInitializer(String source) {
        return insertAfter(source, CLASS_LINE.apply(source),
                "    static {\n        while (System.nanoTime() != 0) {\n            Thread.onSpinWait();\n        }\n    }\n");
    }

    /** TRUE when every test named so passes, FALSE when none does, null when some do. */
    private static Boolean passing(List<Map<String, Object>> tests, Predicate<String> named) {
        List<Boolean> passed = tests.stream().filter(t -> named.test((String) t.get("name"))).map(t -> "passed".equals(t.get("status")))
                .distinct().collect(Collectors.toList());
        return passed.size() == 1 ? passed.get(0) : null;
    }

    /** Every process of a student user (any grading slot's) still alive, as "pid user command". */
    /** The student users' processes left 10 s after the grading ended (none, if it ended them all). */
    private static List<String> studentProcesses() throws InterruptedException {
        return StudentUserProcesses.livingAfter(Sandbox.USER, 10);
    }

    /**
     * Graded within {@code seconds}, leaking nothing the finder knows in any of its encodings into what
     * the student sees, with no process of a student user left; recorded as {@code attack}.
     */
    private static void assertClean(Graded graded, double seconds, String attack) throws Exception {
        List<String> leaks = new ArrayList<>();
        collectStrings(visible(graded), text -> {
            String how = finder.leakIn(text);
            if (how != null) {
                leaks.add(how + ": " + text.substring(0, Math.min(200, text.length())));
            }
        });
        assertEquals("leaks: " + leaks, List.of(), leaks);
        assertTrue(graded.seconds + " s", graded.seconds < seconds);
        assertEquals("no process of a student user is left", List.of(), studentProcesses());
        record(attack, graded, "no");
    }

    /** What the student sees: the results but the hidden tests' entries (a hidden test's failure quotes its own inputs). */
    private static Map<String, Object> visible(Graded graded) {
        Map<String, Object> seen = new LinkedHashMap<>(graded.results);
        seen.put("tests", graded.tests.stream().filter(t -> !"hidden".equals(t.get("visibility"))).collect(Collectors.toList()));
        return seen;
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

    private static synchronized void record(String attack, Graded graded, String leak) throws Exception {
        Files.createDirectories(SUMMARY.getParent());
        String line = String.format("%-56s score %6.1f  %8d bytes  leak %-3s  %6.1f s%n", attack, graded.score(), graded.bytes, leak,
                graded.seconds);
        Files.writeString(SUMMARY, line, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    }
}
