package ray.grading;

import com.google.gson.Gson;
import com.google.gson.reflect.TypeToken;
import java.io.File;
import java.io.IOException;
import java.lang.reflect.Type;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/**
 * Runs graded tests in a separate JVM ({@link TestRunnerMain}) and survives whatever student code
 * does there: a test that calls System.exit, crashes the JVM or hangs past {@link #HARD_LIMIT_SECONDS}
 * is failed, and the JVM is started again for the tests that have not run yet. JUnit's own per-test
 * timeouts catch most infinite loops first; this is the backstop for loops that ignore interrupts.
 */
public final class TestProcess {
    /** No single test may keep the JVM busy longer than this (render tests have a 60 s JUnit limit). */
    public static final int HARD_LIMIT_SECONDS = 120;
    /** Heap for the test JVM: unbounded allocation in student code fails its test, not the grader. */
    static final String HEAP = "-Xmx1g";
    /**
     * How the test JVM runs, besides its heap: it lives a few seconds, most of them starting up and
     * warming up, so C1 alone compiles (C2's compiling, on a core the other gradings want, outlasts
     * what it saves), with the serial collector (no collector threads for a small heap). A correct
     * submission's test JVMs took 17 s of CPU with the defaults and 10 s with these; its render tests
     * 11 s and 6 s. Only work of a minute or more (no test of a correct submission comes near) runs
     * slower with C1 alone, about a quarter.
     */
    static final List<String> SHORT_LIVED_JVM = List.of("-XX:+UseParallelGC");
    private static final int MAX_RESTARTS = 100;
    /**
     * Turns on ray.testing.UnfinishedTasks in the test JVM: after a task's first test that never
     * finishes, its later tests fail at once instead of each waiting out its limit.
     */
    static final String SKIP_AFTER_TIMEOUT = "ray1.grading.skipAfterTimeout";
    /** The tests an earlier test JVM did not finish, for UnfinishedTasks in the next one. */
    static final String UNFINISHED = "ray1.grading.unfinished";
    private static final Gson GSON = new Gson();
    private static final Type EVENT = new TypeToken<Map<String, Object>>() { }.getType();

    private final Path projectDir;
    private final Path classesDir;
    private final String classpath;
    private final Path workDir;
    private int hardLimitSeconds = HARD_LIMIT_SECONDS;
    private boolean includeUngraded;
    private boolean withoutRenderTests;
    /** When (System.nanoTime) the whole grade must stop, and what its unfinished tests then say. */
    private long deadline = Long.MAX_VALUE;
    private String pastDeadline;
    /** Set when watching stopped a test JVM at the deadline. */
    private boolean deadlineReached;
    /** Stand-ins for the task's student classes, first on the judge's class path; null to run the tree's own classes. */
    private Path standIns;
    /** The worker's set-up (a Containment file) the stand-ins ask; null when there are none. */
    private Path workerSetup;
    /** The grade's deadline as a wall-clock time (milliseconds since the epoch), for the judge's calls to the worker. */
    private long deadlineMillis;
    /** The test JVMs started so far, for naming each one's events file apart. */
    private static final java.util.concurrent.atomic.AtomicLong LAUNCHES = new java.util.concurrent.atomic.AtomicLong();

    /**
     * @param projectDir the project tree, the tests' working folder (so that scenes/ resolves)
     * @param classesDir the compiled project (main and test classes)
     * @param classpath  its libraries (JUnit, ...)
     * @param workDir    where the events and output files go
     */
    public TestProcess(Path projectDir, Path classesDir, String classpath, Path workDir) {
        this.projectDir = projectDir;
        this.classesDir = classesDir;
        this.classpath = classpath;
        this.workDir = workDir;
    }

    /**
     * Stops at {@code nanoTime} (System.nanoTime): the test JVM is ended, and every test of the run
     * not finished by then fails with {@code why}, so the points earned so far still count.
     */
    TestProcess withDeadline(long nanoTime, String why) {
        this.deadline = nanoTime;
        this.deadlineMillis = nanoTime == Long.MAX_VALUE ? 0 : System.currentTimeMillis() + (nanoTime - System.nanoTime()) / 1_000_000;
        this.pastDeadline = why;
        return this;
    }

    /** For tests of the grader itself: a shorter backstop. */
    TestProcess withHardLimitSeconds(int seconds) {
        this.hardLimitSeconds = seconds;
        return this;
    }

    /**
     * The judge: the tests run with the stand-ins in {@code standIns} first, which ask the worker that
     * {@code workerSetup} (a {@link ray.grading.judge.Containment} file) starts; this JVM runs no student class.
     */
    TestProcess judging(Path standIns, Path workerSetup) {
        this.standIns = standIns;
        this.workerSetup = workerSetup;
        return this;
    }

    /** Also run the tests without @Points, reported as task 0 worth nothing (to check a whole tree, not to grade). */
    public TestProcess withUngradedTests() {
        this.includeUngraded = true;
        return this;
    }

    /**
     * Only the unit tests: not the whole-scene render tests (package ray.endtoend), which take most
     * of a task's time (to learn which unit tests a known mistake fails).
     */
    TestProcess withoutRenderTests() {
        this.withoutRenderTests = true;
        return this;
    }

    /** Where test sources live; only classes from there are tests (a main class may end in "Test" too). */
    private static final List<String> TEST_SOURCES = List.of("src/test/java", "src/instructorTest/java");

    /**
     * The test classes: every top-level *Test.java under the project's test source folders, by name,
     * the whole-scene render tests (*RenderTest, *RenderBonusTest) last. A loop in student code then
     * meets a unit test's 10 s limit first, and with it ends the task's run (UnfinishedTasks), rather
     * than a render test's 60 s.
     */
    public List<String> testClasses() throws IOException {
        List<String> classes = new ArrayList<>();
        for (String folder : TEST_SOURCES) {
            Path root = projectDir.resolve(folder);
            if (!Files.isDirectory(root)) {
                continue;
            }
            try (Stream<Path> walk = Files.walk(root)) {
                walk.map(p -> root.relativize(p).toString().replace(File.separatorChar, '/'))
                        .filter(n -> n.endsWith("Test.java"))
                        .map(n -> n.substring(0, n.length() - ".java".length()).replace('/', '.'))
                        .forEach(classes::add);
            }
        }
        classes.sort(Comparator.comparing((String c) -> c.matches(".*Render(Bonus)?Test")).thenComparing(Comparator.naturalOrder()));
        return classes;
    }

    /** The graded tests the classes hold (for task {@code task}, or all when null), without running them. */
    public List<TestOutcome> list(Integer task) throws IOException, InterruptedException {
        Path events = eventsFile("list");
        watch(launch(events, task == null ? null : Set.of(task), Set.of(), true, ""), events);
        List<TestOutcome> tests = new ArrayList<>();
        boolean done = false;
        for (Map<String, Object> e : read(events)) {
            if ("test".equals(e.get("event"))) {
                tests.add(outcome(e, false, "not run"));
            }
            done |= "done".equals(e.get("event"));
        }
        // Listing runs the instructor's code alone: a listing that did not finish is the instructor's
        // error, which must stop the grade rather than leave it with no tests (a score of 0 / 0).
        if (!done) {
            Path output = workDir.resolve("test-output.txt");
            String first = Files.exists(output) ? Files.readAllLines(output, java.nio.charset.StandardCharsets.UTF_8).stream()
                    .filter(line -> !line.isBlank()).findFirst().orElse("") : "";
            throw new IllegalStateException("the instructor's tests could not be listed" + (first.isEmpty() ? "" : ": " + first));
        }
        return tests;
    }

    /** Runs the graded tests (of {@code task}, or all when null), in order, and returns every outcome. */
    public List<TestOutcome> run(Integer task) throws IOException, InterruptedException {
        return runTasks(task == null ? null : Set.of(task));
    }

    /** Runs the graded tests of {@code tasks} (all when null), task by task, and returns every outcome. */
    public List<TestOutcome> runTasks(Set<Integer> task) throws IOException, InterruptedException {
        Files.createDirectories(workDir);
        Map<String, TestOutcome> results = new LinkedHashMap<>();
        Set<String> skip = new LinkedHashSet<>();
        for (int attempt = 0; attempt <= MAX_RESTARTS; attempt++) {
            if (System.nanoTime() > deadline) {
                return stoppedAtDeadline(task, results);
            }
            // A file per JVM, so that each attempt's unfinished test is told apart from earlier ones.
            Path events = eventsFile(String.valueOf(attempt));
            int resultsBefore = results.size();
            Process child = launch(events, task, skip, false, unfinished(results.values()));
            boolean finished = watch(child, events);
            Map<String, Map<String, Object>> started = new LinkedHashMap<>();
            boolean done = false;
            boolean restart = false;
            String exited = null;
            for (Map<String, Object> e : read(events)) {
                String test = (String) e.get("test");
                switch (String.valueOf(e.get("event"))) {
                    case "start":
                        started.put(test, e);
                        break;
                    case "finish":
                        Map<String, Object> start = started.remove(test);
                        if (start != null) {
                            start.putAll(e);
                            results.put(test, outcome(start, (Boolean) e.get("passed"), (String) e.get("message")));
                        }
                        break;
                    case "exit":
                        exited = test;
                        break;
                    case "done":
                        done = true;
                        break;
                    case "restart":
                        // A test of an unfinished task hung before its rule: the next JVM skips the task's tests unmade.
                        restart = true;
                        break;
                    default:
                        break;
                }
            }
            if (done) {
                return new ArrayList<>(results.values());
            }
            if (deadlineReached) {
                return stoppedAtDeadline(task, results);
            }
            if (restart && started.isEmpty()) {
                skip.addAll(results.keySet());
                continue;
            }
            // The JVM ended (or was stopped) during the one test that started without finishing.
            for (Map.Entry<String, Map<String, Object>> open : started.entrySet()) {
                String why = !finished ? "stopped after " + hardLimitSeconds + " s: the test never finished (an infinite loop?)"
                        : open.getKey().equals(exited) ? "the code under test called System.exit, which ended the test JVM"
                        : "the test JVM crashed during this test (exit code " + child.exitValue() + ")";
                results.put(open.getKey(), outcome(open.getValue(), false, why));
            }
            if (started.isEmpty() && results.size() == resultsBefore) {
                throw new IllegalStateException("the test JVM ended without running a test (exit code "
                        + child.exitValue() + "); see " + workDir.resolve("test-output.txt"));
            }
            // Ended (or stopped) between tests, or during one: the next JVM runs the tests left.
            skip.addAll(results.keySet());
        }
        throw new IllegalStateException("gave up after " + MAX_RESTARTS + " restarts of the test JVM");
    }

    /**
     * The outcomes when the deadline came: those finished, then every other test of the run (the one
     * running, and those never started) failed with the deadline's reason, in the listed order.
     */
    private List<TestOutcome> stoppedAtDeadline(Set<Integer> tasks, Map<String, TestOutcome> results) throws IOException, InterruptedException {
        long deadlineWas = deadline;
        deadline = Long.MAX_VALUE;
        try {
            List<TestOutcome> all = new ArrayList<>(results.values());
            for (TestOutcome t : list(null)) {
                if ((tasks == null || tasks.contains(t.task())) && !results.containsKey(t.id())) {
                    all.add(t.failedWith(pastDeadline));
                }
            }
            return all;
        } finally {
            deadline = deadlineWas;
        }
    }

    /**
     * The tests that ran out of time in earlier test JVMs, as UnfinishedTasks reads them: the first
     * per task (and per task's bonus tests), {@code TASK=test Class.method} or {@code TASK+bonus=...},
     * a hidden one as "a hidden test".
     */
    static String unfinished(Iterable<TestOutcome> earlier) {
        Map<String, String> first = new LinkedHashMap<>();
        for (TestOutcome t : earlier) {
            if (!t.passed() && (t.message().startsWith("stopped after ") || t.message().contains("took longer than "))) {
                String simpleClass = t.className().substring(t.className().lastIndexOf('.') + 1);
                String test = "hidden".equals(t.visibility()) ? "a hidden test" : "test " + simpleClass + "." + t.method();
                first.putIfAbsent(t.task() + (t.bonus() ? "+bonus" : ""), test);
            }
        }
        List<String> entries = new ArrayList<>();
        first.forEach((key, test) -> entries.add(key + "=" + test));
        return String.join(";", entries);
    }

    /** A new events file for one test JVM, in the grader's work folder, named apart from every other JVM's. */
    private Path eventsFile(String attempt) throws IOException {
        Path folder = workDir;
        Files.createDirectories(folder);
        Path events = folder.resolve("events-" + LAUNCHES.incrementAndGet() + "-" + attempt + ".jsonl");
        Files.deleteIfExists(events);
        return events;
    }

    private Process launch(Path events, Set<Integer> tasks, Set<String> skip, boolean listOnly, String unfinished) throws IOException {
        String self = Path.of(java.net.URI.create(
                TestRunnerMain.class.getProtectionDomain().getCodeSource().getLocation().toString())).toString();
        String fullClasspath = (standIns != null ? standIns + File.pathSeparator : "") + classesDir + File.pathSeparator + classpath
                + File.pathSeparator + self;
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), HEAP,
                "-Djava.awt.headless=true", "-D" + SKIP_AFTER_TIMEOUT + "=true", "-D" + UNFINISHED + "=" + unfinished));
        if (!includeUngraded) {
            // Checking a whole tree (the ungraded tests too) runs long tests: those keep the defaults.
            command.addAll(1, SHORT_LIVED_JVM);
        }
        if (workerSetup != null && !listOnly) {
            command.add("-D" + ray.grading.judge.Judge.WORKER_PROPERTY + "=" + workerSetup);
            if (deadlineMillis > 0) {
                command.add("-D" + ray.grading.judge.Judge.DEADLINE_PROPERTY + "=" + deadlineMillis);
            }
        }
        command.addAll(List.of("-cp", fullClasspath, TestRunnerMain.class.getName(), events.toString()));
        if (tasks != null) {
            command.add("--task");
            command.add(tasks.stream().sorted().map(String::valueOf).collect(java.util.stream.Collectors.joining(",")));
        }
        for (String id : skip) {
            command.add("--skip");
            command.add(id);
        }
        if (listOnly) {
            command.add("--list");
        }
        if (includeUngraded) {
            command.add("--include-ungraded");
        }
        command.addAll(withoutRenderTests ? testClasses().stream().filter(c -> !TestOutcome.isRenderTestClass(c))
                .collect(java.util.stream.Collectors.toList()) : testClasses());
        Path output = workDir.resolve("test-output.txt");
        Files.createDirectories(workDir);
        // Tests run in the tree's folder, so that relative paths such as scenes/ resolve there.
        return new ProcessBuilder(command).directory(projectDir.toFile()).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(output.toFile())).start();
    }

    /** Waits for the child, stopping it when one test runs past the hard limit; false when it had to be stopped. */
    private boolean watch(Process child, Path events) throws IOException, InterruptedException {
        try {
            return watchUntilEnd(child, events);
        } finally {
            // The judge ends its worker; a judge that had to be stopped leaves that to this, and to the sandbox.
            child.descendants().forEach(ProcessHandle::destroyForcibly);
            child.destroyForcibly();
        }
    }

    private boolean watchUntilEnd(Process child, Path events) throws IOException, InterruptedException {
        deadlineReached = false;
        long sizeSeen = -1;
        long lastProgress = System.nanoTime();
        while (!child.waitFor(200, TimeUnit.MILLISECONDS)) {
            if (System.nanoTime() > deadline) {
                child.destroyForcibly().waitFor();
                deadlineReached = true;
                return false;
            }
            // The events file grows by a line per test started or finished: its size is the progress.
            long size = Files.exists(events) ? Files.size(events) : 0;
            if (size != sizeSeen) {
                sizeSeen = size;
                lastProgress = System.nanoTime();
            } else if (System.nanoTime() - lastProgress > TimeUnit.SECONDS.toNanos(hardLimitSeconds)) {
                child.destroyForcibly().waitFor();
                return false;
            }
        }
        return true;
    }

    private static List<Map<String, Object>> read(Path events) throws IOException {
        List<Map<String, Object>> list = new ArrayList<>();
        if (Files.exists(events)) {
            for (String line : Files.readAllLines(events, StandardCharsets.UTF_8)) {
                if (!line.isBlank()) {
                    list.add(GSON.fromJson(line, EVENT));
                }
            }
        }
        return list;
    }

    private static TestOutcome outcome(Map<String, Object> e, boolean passed, String message) {
        Object seconds = e.get("seconds");
        return new TestOutcome((String) e.get("test"), (String) e.get("class"), (String) e.get("method"),
                ((Number) e.get("task")).intValue(), (String) e.get("title"), ((Number) e.get("points")).doubleValue(),
                Boolean.TRUE.equals(e.get("bonus")), (String) e.get("visibility"), passed, message == null ? "" : message,
                seconds == null ? 0 : ((Number) seconds).doubleValue());
    }
}
