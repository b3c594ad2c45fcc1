package ray.grading;

import com.google.gson.Gson;
import java.io.IOException;
import java.io.Writer;
import java.lang.annotation.Annotation;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.runner.Description;
import org.junit.runner.JUnitCore;
import org.junit.runner.Request;
import org.junit.runner.manipulation.Filter;
import org.junit.runner.notification.Failure;
import org.junit.runner.notification.RunListener;

/**
 * Runs graded tests in a child JVM for {@link TestProcess}, reporting each as one JSON line in an
 * events file as it starts and finishes, so that the parent knows which test was running if the
 * JVM dies (System.exit, a crash) or hangs.
 *
 * <p>Usage: {@code TestRunnerMain EVENTS [--task N] [--skip ID]... [--list] [--include-ungraded] CLASS...}.
 * With {@code --list} it only reports the graded tests it would run; with {@code --include-ungraded}
 * it also runs the tests without {@code @Points} (as task 0, worth nothing).
 */
public final class TestRunnerMain {
    private static final Gson GSON = new Gson();

    private final Writer events;
    private final boolean includeUngraded;
    private volatile String running;
    /** When the running test started (System.nanoTime), and the message it is skipped with if its task was already unfinished then. */
    private volatile long runningSince;
    private volatile String runningSkippedWith;
    /** The running test's grading, and whether its class grades with ray.testing.StudentTaskRule. */
    private volatile Map<String, Object> runningGrading;
    private volatile boolean runningUsesRule;
    /** How long making a test object may take (the unit tests' limit, plus the JVM's slack) before the JVM restarts. */
    private static final int MAKING_LIMIT_SECONDS = 10;
    private static final long MAKING_NANOS = java.util.concurrent.TimeUnit.SECONDS.toNanos(MAKING_LIMIT_SECONDS + 2);
    /** How long a test of an unfinished task may take to reach its rule (which skips it at once) before the JVM restarts. */
    private static final long STUCK_NANOS = java.util.concurrent.TimeUnit.SECONDS.toNanos(3);

    private TestRunnerMain(Writer events, boolean includeUngraded) {
        this.events = events;
        this.includeUngraded = includeUngraded;
    }

    public static void main(String[] args) throws Exception {
        Path eventsFile = Path.of(args[0]);
        Set<Integer> task = null;
        Set<String> skip = new HashSet<>();
        boolean listOnly = false;
        boolean includeUngraded = false;
        List<String> classes = new ArrayList<>();
        for (int i = 1; i < args.length; i++) {
            switch (args[i]) {
                case "--task":
                    task = new HashSet<>();
                    for (String n : args[++i].split(",")) {
                        task.add(Integer.parseInt(n));
                    }
                    break;
                case "--skip":
                    skip.add(args[++i]);
                    break;
                case "--list":
                    listOnly = true;
                    break;
                case "--include-ungraded":
                    includeUngraded = true;
                    break;
                default:
                    classes.add(args[i]);
            }
        }
        try (Writer events = Files.newBufferedWriter(eventsFile, StandardCharsets.UTF_8, StandardOpenOption.CREATE,
                StandardOpenOption.APPEND)) {
            TestRunnerMain runner = new TestRunnerMain(events, includeUngraded);
            // When grading, the stand-ins of the task's student classes ask the worker (ray.grading.judge).
            ray.grading.judge.Judge.start();
            // System.exit in a test ends the JVM; say which test did it before it goes.
            Runtime.getRuntime().addShutdownHook(new Thread(runner::reportExitDuringTest));
            if (!listOnly) {
                runner.watchForStuckTests();
            }
            try {
                runner.run(classes, task, skip, listOnly);
            } finally {
                ray.grading.judge.Judge.stop();
            }
            runner.write(Map.of("event", "done"));
        }
        // Stray threads of timed-out tests must not keep this JVM alive.
        Runtime.getRuntime().halt(0);
    }

    /**
     * A test of a task whose code already never finished is failed by its rule at once; one still
     * running after {@link #STUCK_NANOS} never reached the rule, stuck while JUnit made its object
     * (a field that needs a class whose static initializer never ends). This JVM cannot free that
     * thread, so the test is reported skipped and the JVM asks to be restarted ("restart"), in which
     * the task's remaining tests are skipped before any is made.
     */
    private void watchForStuckTests() {
        Thread watcher = new Thread(() -> {
            while (true) {
                try {
                    Thread.sleep(250);
                } catch (InterruptedException e) {
                    return;
                }
                String test = running;
                if (test == null || !runningUsesRule) {
                    continue;
                }
                long elapsed = System.nanoTime() - runningSince;
                String skipped = runningSkippedWith;
                String message = null;
                if (skipped != null && elapsed > STUCK_NANOS) {
                    message = skipped;
                } else if (elapsed > MAKING_NANOS && !test.equals(ruleEntered())) {
                    // Its rule never began: JUnit is still making the test object, running student code with no limit.
                    message = stuckBeforeTheTest(runningGrading);
                }
                if (message != null) {
                    try {
                        write(Map.of("event", "finish", "test", test, "passed", false, "message", message,
                                "seconds", elapsed / 1e9));
                        write(Map.of("event", "restart"));
                    } catch (IOException e) {
                        // The parent then sees a JVM that ended during the test.
                    }
                    Runtime.getRuntime().halt(0);
                }
            }
        }, "ray1-stuck-test-watcher");
        watcher.setDaemon(true);
        watcher.start();
    }

    /** The test whose StudentTaskRule began last (ray.testing.UnfinishedTasks), or null. */
    private static String ruleEntered() {
        try {
            return (String) unfinishedTasks().getMethod("lastEntered").invoke(null);
        } catch (ReflectiveOperationException | LinkageError | RuntimeException e) {
            return null;
        }
    }

    /** The message of a test stuck while its object was made, under its task. */
    private static String stuckBeforeTheTest(Map<String, Object> grading) {
        try {
            return (String) unfinishedTasks().getMethod("stuckBeforeTheTest", int.class, boolean.class, int.class)
                    .invoke(null, ((Number) grading.get("task")).intValue(), Boolean.TRUE.equals(grading.get("bonus")), MAKING_LIMIT_SECONDS);
        } catch (ReflectiveOperationException | LinkageError | RuntimeException e) {
            return "took longer than " + MAKING_LIMIT_SECONDS + " s before the test itself began";
        }
    }

    private static Class<?> unfinishedTasks() throws ClassNotFoundException {
        return Class.forName("ray.testing.UnfinishedTasks", true, Thread.currentThread().getContextClassLoader());
    }

    /** Whether the test class grades with ray.testing.StudentTaskRule (a public @Rule field, its own or inherited). */
    static boolean usesStudentRule(Class<?> type) {
        for (java.lang.reflect.Field field : type.getFields()) {
            if (field.isAnnotationPresent(org.junit.Rule.class) && field.getType().getName().equals("ray.testing.StudentTaskRule")) {
                return true;
            }
        }
        return false;
    }

    /**
     * The message a test of this grading is skipped with because its task's code never finished in an
     * earlier test (ray.testing.UnfinishedTasks, in the test classes), or null to run it.
     */
    private static String skippedBecauseUnfinished(Map<String, Object> grading) {
        if (grading == null || ((Number) grading.get("task")).intValue() <= 0) {
            return null;
        }
        try {
            return (String) unfinishedTasks().getMethod("skipped", int.class, boolean.class)
                    .invoke(null, ((Number) grading.get("task")).intValue(), Boolean.TRUE.equals(grading.get("bonus")));
        } catch (ReflectiveOperationException | LinkageError | RuntimeException e) {
            return null;
        }
    }

    private void run(List<String> classNames, Set<Integer> task, Set<String> skip, boolean listOnly) throws Exception {
        JUnitCore core = new JUnitCore();
        Reporter reporter = new Reporter();
        core.addListener(reporter);
        // Task by task (in the order given within a task, render tests last): each task's worker starts once.
        // A task's hidden tests come after all its others: what its code sees of their inputs can reach
        // only their own (hidden) messages, since the task's worker and its files end with them.
        List<Class<?>> types = new ArrayList<>();
        for (String name : classNames) {
            types.add(Class.forName(name, false, TestRunnerMain.class.getClassLoader()));
        }
        types.sort(java.util.Comparator.comparingInt(TestRunnerMain::taskOf).thenComparing(type -> !visible(type)));
        for (Class<?> type : types) {
            if (java.lang.reflect.Modifier.isAbstract(type.getModifiers())) {
                continue;
            }
            // Tests of a task whose code never finished are failed without being made (their fields may
            // hang), as their StudentTaskRule would fail them once made.
            Map<String, Description> skippedUnmade = new LinkedHashMap<>();
            boolean usesRule = usesStudentRule(type);
            Filter filter = new Filter() {
                @Override
                public boolean shouldRun(Description d) {
                    if (!d.isTest()) {
                        return d.getChildren().stream().anyMatch(this::shouldRun);
                    }
                    Map<String, Object> grade = metadata(d);
                    boolean selected = grade != null && (task == null || task.contains(((Number) grade.get("task")).intValue()))
                            && !skip.contains(idOf(d));
                    if (selected && !listOnly && usesRule && skippedBecauseUnfinished(grading(d)) != null) {
                        skippedUnmade.put(idOf(d), d);
                        return false;
                    }
                    return selected;
                }

                @Override
                public String describe() {
                    return "graded tests";
                }
            };
            Request request = Request.aClass(type).filterWith(filter);
            if (listOnly) {
                listTests(request.getRunner().getDescription());
            } else if (filter.shouldRun(Request.aClass(type).getRunner().getDescription())) {
                // While grading, the class's task is the one whose student classes the worker runs.
                ray.grading.judge.Judge.grade(taskOf(type));
                core.run(request);
            }
            for (Description d : skippedUnmade.values()) {
                reporter.testStarted(d);
                reporter.testSkipped(d, skippedBecauseUnfinished(grading(d)));
                reporter.testFinished(d);
            }
        }
    }

    /** Whether a test class's @Points shows its results to students at once (not a hidden test). */
    private static boolean visible(Class<?> type) {
        Annotation points = PointsAnnotation.ofClass(type);
        return points == null || "visible".equals(PointsAnnotation.field(points, "visibility", "gradescope"));
    }

    /** The number of a graded test class's task in this assignment ({@link GradedTask}); 0 for none. */
    private static int taskOf(Class<?> type) {
        return PointsAnnotation.ofClass(type) == null ? 0 : GradedTask.of(type.getName()).map(GradedTask::number).orElse(0);
    }

    private void listTests(Description d) throws IOException {
        if (d.isTest()) {
            Map<String, Object> e = metadata(d);
            if (e != null && !d.getDisplayName().startsWith("initializationError")) {
                e.put("event", "test");
                e.put("test", idOf(d));
                write(e);
            }
        }
        for (Description child : d.getChildren()) {
            listTests(child);
        }
    }

    /** "ClassName#method": JUnit's description names a test "method(ClassName)". */
    static String idOf(Description d) {
        return d.getClassName() + "#" + d.getMethodName();
    }

    /** What is reported of a test: its grading, or for an ungraded test (when those run) task 0 and no points. */
    private Map<String, Object> metadata(Description d) {
        Map<String, Object> m = grading(d);
        if (m == null && includeUngraded) {
            m = new LinkedHashMap<>();
            m.put("task", 0);
            m.put("title", "ungraded");
            m.put("points", 0.0);
            m.put("bonus", false);
            m.put("visibility", "visible");
            m.put("class", d.getClassName());
            m.put("method", d.getMethodName());
        }
        return m;
    }

    /**
     * The test's grading: its task's number and title in this assignment, its @Points' points, bonus
     * (its own, or its task's extra credit) and visibility; null for ungraded tests, among them the
     * tests of a task the assignment does not choose.
     */
    private static Map<String, Object> grading(Description d) {
        Annotation points = PointsAnnotation.of(d);
        GradedTask task = points == null ? null : GradedTask.of(d.getClassName()).orElse(null);
        if (task == null) {
            return null;
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("task", task.number());
        m.put("title", task.title());
        m.put("points", PointsAnnotation.element(points, "value"));
        m.put("bonus", (Boolean) PointsAnnotation.element(points, "bonus") || task.extraCredit());
        m.put("visibility", PointsAnnotation.field(points, "visibility", "gradescope"));
        m.put("class", d.getClassName());
        m.put("method", d.getMethodName());
        return m;
    }

    private synchronized void write(Map<String, Object> event) throws IOException {
        events.write(GSON.toJson(event));
        events.write('\n');
        events.flush();
    }

    private void reportExitDuringTest() {
        String test = running;
        if (test != null) {
            try {
                write(Map.of("event", "exit", "test", test));
            } catch (IOException e) {
                // The parent reports the test as a crash instead.
            }
        }
    }

    private final class Reporter extends RunListener {
        private final Map<String, Long> started = new LinkedHashMap<>();
        private final Map<String, String> failures = new LinkedHashMap<>();

        @Override
        public void testStarted(Description d) throws IOException {
            String id = idOf(d);
            runningSince = System.nanoTime();
            runningGrading = grading(d);
            runningSkippedWith = skippedBecauseUnfinished(runningGrading);
            runningUsesRule = d.getTestClass() != null && usesStudentRule(d.getTestClass());
            running = id;
            started.put(id, System.nanoTime());
            Map<String, Object> e = metadata(d);
            e.put("event", "start");
            e.put("test", id);
            write(e);
        }

        @Override
        public void testFailure(Failure failure) {
            failures.put(idOf(failure.getDescription()), explain(failure.getException(), grading(failure.getDescription())));
        }

        /** Fails a test that is not run at all, with why. */
        void testSkipped(Description d, String why) {
            failures.put(idOf(d), why);
        }

        @Override
        public void testAssumptionFailure(Failure failure) {
            failures.put(idOf(failure.getDescription()), "skipped: " + failure.getMessage());
        }

        @Override
        public void testFinished(Description d) throws IOException {
            String id = idOf(d);
            Map<String, Object> e = new LinkedHashMap<>();
            e.put("event", "finish");
            e.put("test", id);
            e.put("passed", !failures.containsKey(id));
            // Student code chooses its messages: a 5 MB one would make every events line, and every read of them, huge.
            e.put("message", OutputLimits.cut(failures.getOrDefault(id, ""), OutputLimits.MESSAGE_CHARS));
            e.put("seconds", (System.nanoTime() - started.getOrDefault(id, System.nanoTime())) / 1e9);
            write(e);
            running = null;
        }
    }

    /**
     * The failure's message and where in the project's code it happened (a few frames, not the whole
     * trace). What escaped the test's own rule (an error while JUnit made the test class, such as a
     * student's static initializer running out of memory) is named as the rule would name it, under
     * the test's task ({@code grading}, null for an ungraded test).
     */
    static String explain(Throwable t, Map<String, Object> grading) {
        String message;
        if (t instanceof AssertionError && t.getMessage() != null) {
            // An assertion's message says it all.
            message = t.getMessage();
        } else if (grading != null && ((Number) grading.get("task")).intValue() > 0) {
            message = "[Task " + ((Number) grading.get("task")).intValue() + " (" + grading.get("title") + ")"
                    + (Boolean.TRUE.equals(grading.get("bonus")) ? ", bonus" : "") + "] " + studentWords(t);
        } else {
            // Any other throwable also needs its class ("OutOfMemoryError: ...").
            message = t.toString();
        }
        StringBuilder s = new StringBuilder(message);
        int frames = 0;
        for (StackTraceElement f : t.getStackTrace()) {
            String c = f.getClassName();
            // The test harness, the grader and the hidden tests are no business of the student's.
            if (c.startsWith("ray.") && !c.startsWith("ray.testing.") && !c.startsWith("ray.grading.") && !c.startsWith("ray.hidden.")
                    && frames < 6) {
                // Class, method, file and line; not the class loader's or module's name before them.
                s.append("\n    at ").append(c).append('.').append(f.getMethodName()).append('(').append(f.getFileName())
                        .append(':').append(f.getLineNumber()).append(')');
                frames++;
            }
        }
        return s.toString();
    }

    /** The tests' own words for what student code threw (ray.testing.StudentTaskRule, in the test classes). */
    private static String studentWords(Throwable t) {
        try {
            return (String) Class.forName("ray.testing.StudentTaskRule", true, Thread.currentThread().getContextClassLoader())
                    .getMethod("whatWentWrong", Throwable.class).invoke(null, t);
        } catch (ReflectiveOperationException | LinkageError | RuntimeException e) {
            return "your code threw " + t;
        }
    }
}
