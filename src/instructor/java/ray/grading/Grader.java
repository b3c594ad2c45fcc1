package ray.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The autograder ({@code gradle grade [-Psubmission=DIR|ZIP]}): runs every graded test and writes
 * Gradescope's results.json (or PrairieLearn's, with {@code --format prairielearn}).
 *
 * <p>A submission is graded task by task: the tests of task N run on the instructor's tree with
 * only task N's files the student's (compiled against the instructor's classes, which are compiled
 * once per run, and put first on the test JVM's class path). So a broken sphere costs the
 * sphere's points and nothing else, and no test needs its own copy of the solution. That holds for
 * a file that does not compile too: a missing brace in Triangle.java fails Task 3's tests, with the
 * compiler's messages, and no other task's. Without a submission, the instructor's own tree is
 * graded (it should score full marks, and every bonus point on top).
 *
 * <p>Each run works in a folder of its own under {@code --out} (removed afterwards), so runs at once
 * never meet; and it always writes results.json, with a score of 0 and the reason when the grader
 * itself fails (say, a submission path that does not exist), never leaving an earlier result in place.
 */
@Command(name = "grade", mixinStandardHelpOptions = true, description = "Grades the instructor tree or a submission.")
public final class Grader implements Callable<Integer> {
    @Option(names = "--project", required = true, description = "The instructor's project folder.")
    Path project;

    @Option(names = "--classpath", required = true, description = "Libraries the tests need (JUnit, ...).")
    String classpath;

    @Option(names = "--submission", description = "A folder or zip with the student's files.")
    Path submission;

    @Option(names = "--out", description = "Work folder; results.json goes here (default: ${DEFAULT-VALUE}).")
    Path out = Path.of("build/grade");

    @Option(names = "--results", description = "Also write results.json here (Gradescope: /autograder/results/results.json).")
    Path resultsCopy;

    /** The platform whose results.json to write; both come from the same outcomes. */
    enum Format { gradescope, prairielearn }

    @Option(names = "--format", description = "results.json for ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE}).")
    Format format = Format.gradescope;

    @Option(names = "--time-limit", description = "Seconds for the whole grade; tests not finished by then fail and the"
            + " points earned so far count (0: no limit; run_autograder and PrairieLearn's run set one below the platform's).")
    int timeLimitSeconds;

    @Option(names = "--no-isolation", negatable = false, description = "Run student code as the grader's own user even as root.")
    boolean noIsolation;

    @Mixin
    AssignmentOptions assignment = new AssignmentOptions();

    @Option(names = "--task", description = "Grade only this task's tests (a regrade of one task, or the diagnosis evaluation).")
    Integer onlyTask;

    // PrairieLearn shows every test it is given; Gradescope hides tests by their visibility itself.
    // The environment variable lets a PrairieLearn question's info.json choose, without another entrypoint.
    @Option(names = "--hidden-tests", defaultValue = "${env:RAY1_HIDDEN_TESTS:-summary}",
            description = "PrairieLearn: hidden tests as one line per task (summary) or one unnamed entry each (each);"
                    + " ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE}, from RAY1_HIDDEN_TESTS when set).")
    PrairieLearnResults.HiddenTests hiddenTests;

    public static void main(String[] args) {
        System.exit(new CommandLine(new Grader()).execute(args));
    }

    /** gradeAll's instructor tree, compiled once for the whole class; null when this run compiles its own. */
    private final CompiledTree sharedTree;

    public Grader() {
        this(null, 0);
    }

    /**
     * A grader that copies {@code sharedTree} (which it only reads) instead of compiling the
     * instructor's tree, and runs the submission's code as grading slot {@code slot}'s user (gradeAll
     * grades several submissions at once, each as a user of its own).
     */
    Grader(CompiledTree sharedTree, int slot) {
        this.sharedTree = sharedTree;
        this.slot = slot;
    }

    /** Which of gradeAll's gradings at once this is: its student code runs as that slot's user. */
    private int slot;

    /** This run's own work folder under {@code out}. */
    private Path work;
    /** Where, and as whom, the workers run student code (Sandbox); made once the instructor's tree is compiled. */
    private Sandbox sandbox;
    /** The instructor's tests, by task, as the tree lists them: the only tests that count, worth what they say. */
    private final Map<Integer, List<TestOutcome>> listed = new LinkedHashMap<>();
    /** The known mistakes failed tests' results are, by test id (VariantMistakes). */
    private final Map<String, String> mistakeNames = new LinkedHashMap<>();

    /** System.nanoTime when the grade must stop (--time-limit). */
    private long deadline = Long.MAX_VALUE;

    @Override
    public Integer call() throws Exception {
        // The assignment is the process's while this grade runs (a test may grade several in one JVM).
        ray.assignment.Assignment before = ray.assignment.Assignment.current();
        try {
            return grade();
        } finally {
            ray.assignment.Assignment.use(before);
        }
    }

    private Integer grade() throws Exception {
        long start = System.nanoTime();
        if (timeLimitSeconds > 0) {
            deadline = start + java.util.concurrent.TimeUnit.SECONDS.toNanos(timeLimitSeconds);
        }
        StringBuilder output = new StringBuilder();
        List<TestOutcome> outcomes;
        Map<String, RenderFeedback.Shown> pictures;
        Redaction redaction;
        Path resultsFile = out.resolve("results.json");
        try {
            // The assignment graded: the project's file (in a grading package, the one it was packed with), or the one given.
            if (sharedTree == null) {
                ray.assignment.Assignment.use(assignment.resolve(project));
            }
            Files.createDirectories(out);
            work = Files.createTempDirectory(out, "work-");
            outcomes = gradeSubmission(output);
            // Nothing the student's code started may still be running when the results are written.
            sandbox.endStrayProcesses();
            // Student code can read the grading tree: nothing it quotes from the instructor's files reaches the results.
            redaction = Redaction.of(project);
            outcomes = OutputLimits.cutMessages(redaction.redact(outcomes), OutputLimits.MESSAGE_CHARS);
            // No path on the grading machine reaches the student: the render tests' report line names one.
            outcomes = outcomes.stream().map(t -> t.withMessage(RenderFeedback.withoutReportLine(t.message())))
                    .collect(java.util.stream.Collectors.toList());
            // A unit test's known mistake goes in its message; a render test's on its page (RenderFeedback).
            outcomes = outcomes.stream().map(t -> mistakeNames.containsKey(t.id()) && !t.isRenderTest()
                    ? t.withMessage(t.message() + "\n" + mistakeNames.get(t.id())) : t).collect(java.util.stream.Collectors.toList());
            // Taken now: the render tests' pictures are in the work folder, which goes below.
            pictures = RenderFeedback.of(outcomes, instructorTree(), mistakeNames);
        } catch (Exception | Error e) {
            // Whatever went wrong, the platform reads a result: 0 points and why, not an earlier student's file.
            String why = "The autograder could not grade this submission: " + (e.getMessage() == null ? e.toString() : e.getMessage());
            writeResults(format == Format.prairielearn ? PrairieLearnResults.notGradable(output + why)
                    : GradescopeResults.of(List.of(), output + why + "\n", (System.nanoTime() - start) / 1e9), resultsFile);
            System.err.println("error: " + why);
            return 1;
        } finally {
            if (sandbox != null) {
                sandbox.close();
            }
            if (work != null) {
                ProjectTree.deleteRecursively(work);
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        String shown = redaction.redact(output.toString());
        Map<String, RenderFeedback.Shown> feedback = pictures;
        // Student code chooses its messages and output: the file stays within the platforms' limit.
        Map<String, Object> results = OutputLimits.within(outcomes, shown, (cutOutcomes, cutOutput, withPictures) -> {
            Map<String, RenderFeedback.Shown> shownPictures = withPictures ? feedback : Map.of();
            Map<String, String> pages = new LinkedHashMap<>();
            shownPictures.forEach((id, p) -> pages.put(id, p.html));
            return format == Format.prairielearn ? PrairieLearnResults.of(cutOutcomes, cutOutput, shownPictures, hiddenTests)
                    : GradescopeResults.of(cutOutcomes, cutOutput, seconds, pages);
        });
        writeResults(results, resultsFile);
        System.out.print(output);
        System.out.print(GradescopeResults.table(outcomes));
        for (TestOutcome t : outcomes) {
            if (!t.passed()) {
                System.out.println("FAILED " + t.id() + ": " + t.message().lines().findFirst().orElse(""));
            }
        }
        // The file that outlives this run: the platform's copy when there is one (--out may be a folder deleted afterwards).
        System.out.println("results: " + (resultsCopy != null ? resultsCopy : resultsFile));
        return 0;
    }

    /**
     * Writes the results (atomically: a reader never sees half a file) and reads each file back: what
     * the platform reads must be what the grader wrote, not a file some leftover process put there.
     */
    private void writeResults(Map<String, Object> results, Path resultsFile) throws IOException {
        String expected = GradescopeResults.json(results);
        for (Path file : resultsCopy == null ? List.of(resultsFile) : List.of(resultsFile, resultsCopy)) {
            ReadableFiles.writeAtomically(file, expected);
            if (!Files.readString(file, StandardCharsets.UTF_8).equals(expected)) {
                throw new IOException(file + " changed after the grader wrote it: something else writes there");
            }
        }
    }

    /**
     * Grades the submission (or, without one, the instructor tree's own student files) task by task. The
     * instructor's tree is copied and compiled once, with the handout's classes for the workers and the
     * stand-ins for the judges ({@link GradingClasses}); each task's files then compile against the
     * handout alone, and the task's tests run in a judge whose stand-ins ask a worker that runs those
     * classes, so that every other class (framework, tests, the other tasks) is the solution's, and
     * none of them reaches the student's code.
     */
    private List<TestOutcome> gradeSubmission(StringBuilder output) throws IOException, InterruptedException {
        Map<String, Integer> studentFiles = StudentFiles.in(project);
        if (onlyTask != null && !studentFiles.containsValue(onlyTask)) {
            throw new IllegalArgumentException("--task " + onlyTask + ": there is no such task; the tasks are "
                    + new TreeSet<>(studentFiles.values()));
        }
        Map<String, Path> overlay = new LinkedHashMap<>();
        if (submission == null) {
            studentFiles.keySet().forEach(file -> overlay.put(file, project.resolve(file)));
        } else {
            Submission handedIn = Submission.locate(submission, studentFiles.keySet(), work.resolve("submission"));
            overlay.putAll(handedIn.files);
            describe(handedIn, output);
            for (String missing : handedIn.missing) {
                // A file not handed in counts as the untouched handout's stub.
                Path stub = work.resolve("stubs").resolve(missing);
                Files.createDirectories(stub.getParent());
                String solution = Files.readString(project.resolve(missing), StandardCharsets.UTF_8);
                Files.writeString(stub, SolutionMarkers.studentVersion(solution, missing), StandardCharsets.UTF_8);
                overlay.put(missing, stub);
            }
        }
        Path instructor = instructorTree();
        sandbox = Sandbox.create(GradingClasses.handout(instructor), !noIsolation, slot);
        if (sandbox.warning() != null) {
            System.err.println("warning: " + sandbox.warning());
        }
        // Each task's files compile on their own; the tasks that compiled are judged in one judge, each
        // with its own worker, running its own classes.
        Map<Integer, List<TestOutcome>> byTask = new java.util.TreeMap<>();
        Path workers = work.resolve("workers");
        Files.createDirectories(workers);
        Set<Integer> judged = new TreeSet<>();
        Map<Integer, Map<String, Path>> filesOf = new java.util.TreeMap<>();
        Map<Integer, StudentCompiler.Unit> units = new java.util.TreeMap<>();
        for (int task : new TreeSet<>(studentFiles.values())) {
            if (onlyTask != null && task != onlyTask) {
                continue;
            }
            Map<String, Path> taskFiles = new LinkedHashMap<>();
            overlay.forEach((path, file) -> {
                if (studentFiles.get(path) == task) {
                    taskFiles.put(path, file);
                }
            });
            filesOf.put(task, taskFiles);
            units.put(task, unitOf(task, taskFiles, instructor));
        }
        // Each task's files compile on their own (in a JVM of their own, within a time limit).
        Map<StudentCompiler.Unit, CompileResult> compiled = StudentCompiler.compile(new ArrayList<>(units.values()), deadline);
        for (Map.Entry<Integer, StudentCompiler.Unit> unit : units.entrySet()) {
            int task = unit.getKey();
            String refused = refusal(task, filesOf.get(task), unit.getValue(), compiled.get(unit.getValue()), output);
            if (refused != null) {
                byTask.put(task, allFailed(task, refused));
            } else {
                sandbox.containment(unit.getValue().classes, "task-" + task).write(workers.resolve("task-" + task));
                judged.add(task);
            }
        }
        if (!judged.isEmpty()) {
            TestProcess tests = timed(new TestProcess(instructor, instructor.resolve("classes"), classpath, work.resolve("test-run"))
                    .judging(GradingClasses.standIns(instructor), workers));
            List<TestOutcome> ran;
            try {
                ran = tests.runTasks(judged);
            } catch (IllegalStateException e) {
                ran = List.of();
                for (int task : judged) {
                    byTask.put(task, allFailed(task, "the tests could not run: " + e.getMessage()));
                }
            } finally {
                // Nothing of the student's outlives the tests.
                sandbox.endStrayProcesses();
            }
            for (int task : judged) {
                byTask.putIfAbsent(task, judged(task, ran));
            }
        }
        List<TestOutcome> outcomes = new ArrayList<>();
        for (Map.Entry<Integer, List<TestOutcome>> task : byTask.entrySet()) {
            outcomes.addAll(task.getValue());
            // A known mistake, named, is its fix: a task whose hints are at goal gets the tests' own messages only.
            if (judged.contains(task.getKey()) && fixesShown(task.getKey())) {
                nameMistakes(instructor, task.getKey(), task.getValue(), studentFiles, work.resolve("task-" + task.getKey()).resolve("mistakes"));
            }
        }
        return outcomes;
    }

    /** Whether task {@code number}'s feedback may name causes and fixes: its hint level is not goal. */
    private static boolean fixesShown(int number) {
        ray.assignment.Assignment assignment = ray.assignment.Assignment.current();
        return assignment.task(number).map(t -> assignment.hints(t.id()) != ray.assignment.HintLevel.GOAL).orElse(true);
    }

    /** One task's compilation: its files copied to task-N, compiled against the handout into task-N/classes. */
    private StudentCompiler.Unit unitOf(int task, Map<String, Path> taskFiles, Path instructor) throws IOException {
        Path taskDir = work.resolve("task-" + task);
        List<Path> sources = new ArrayList<>();
        for (Map.Entry<String, Path> file : taskFiles.entrySet()) {
            Path copy = taskDir.resolve(file.getKey());
            Files.createDirectories(copy.getParent());
            Files.copy(file.getValue(), copy, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            sources.add(copy);
        }
        return new StudentCompiler.Unit(taskDir, sources, taskDir.resolve("classes"), GradingClasses.handout(instructor).toString());
    }

    /** Why a task's tests cannot run (its files do not compile, or define classes they may not), or null. */
    private static String refusal(int task, Map<String, Path> taskFiles, StudentCompiler.Unit unit, CompileResult compiled,
            StringBuilder output) throws IOException {
        String files = String.join(", ", taskFiles.keySet());
        String why = null;
        if (!compiled.ok()) {
            // Only this task's tests fail: each other task is graded with its own files, which may compile.
            why = "Task " + task + "'s files (" + files + ") do not compile with the rest of the handout, so its"
                    + " tests could not run; the other tasks are graded on their own. (If they compile in your project,"
                    + " do they use something you changed in another task's file?)\n" + compiled.messages();
        } else {
            String refused = StudentClasses.refused(unit.classes, taskFiles.keySet());
            if (refused != null) {
                why = "Task " + task + "'s files (" + files + ") were not graded: " + refused;
            }
        }
        if (why != null) {
            output.append(why).append('\n');
        }
        return why;
    }

    /** The task's outcomes as the instructor's list has them ({@link ListedOutcomes}). */
    private List<TestOutcome> judged(int task, List<TestOutcome> ran) throws IOException, InterruptedException {
        return ListedOutcomes.judged(listedTests(task), ran);
    }

    /**
     * The instructor's graded tests of {@code task} (every task's when null), all listed at once, in the
     * judge's JVM, once per run (under gradeAll, once for the class).
     */
    private List<TestOutcome> listedTests(Integer task) throws IOException, InterruptedException {
        Path tree = instructorTree();
        List<TestOutcome> all;
        synchronized (listed) {
            all = listed.get(null);
            if (all == null) {
                all = sharedTree != null ? sharedTree.tests(null, () -> tests(tree).list(null)) : List.copyOf(tests(tree).list(null));
                all = TaskPoints.shared(all, ray.assignment.Assignment.current());
                listed.put(null, all);
            }
        }
        return task == null ? all : all.stream().filter(t -> t.task() == task).collect(java.util.stream.Collectors.toList());
    }

    /**
     * When some of the task's tests failed, the known mistakes of the task that the student's results
     * are, measured (kept for {@link RenderFeedback} and the unit tests' messages); never a reason to
     * fail grading.
     */
    private void nameMistakes(Path instructor, int task, List<TestOutcome> taskOutcomes, Map<String, Integer> studentFiles,
            Path mistakesWork) {
        if (taskOutcomes.stream().allMatch(TestOutcome::passed) || System.nanoTime() > deadline) {
            return;
        }
        try {
            // What a mistake does depends on no submission: under gradeAll, each is measured once for
            // the class, from the compiled tree's variants (not this tree's copy).
            MistakeEvidence evidence = sharedTree != null ? sharedTree.mistakeEvidence() : new MistakeEvidence();
            Path variants = sharedTree != null ? sharedTree.root() : instructor;
            mistakeNames.putAll(VariantMistakes.named(instructor, instructor, taskOutcomes,
                    VariantMistakes.of(variants, task, studentFiles), classpath, mistakesWork, evidence));
        } catch (IOException | RuntimeException e) {
            // The feedback goes without a name; the grade is unchanged.
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The tests, stopped at this grade's deadline. */
    private TestProcess timed(TestProcess tests) {
        return tests.withDeadline(deadline, pastDeadline());
    }

    /** What a test not finished by the deadline says. */
    private String pastDeadline() {
        return "not run: grading stopped at its time limit of " + timeLimitSeconds + " s, before this test finished;"
                + " the points of the tests before it count. (Do some tests take many seconds each? A correct"
                + " submission is graded in well under a minute.)";
    }

    /**
     * The instructor's tree, copied and compiled once per run (the classes every task's tests run on);
     * under gradeAll, a copy of the tree it compiled once for the class.
     */
    private Path instructorTree() throws IOException {
        Path tree = work.resolve("instructor");
        if (sharedTree != null && !Files.exists(tree)) {
            sharedTree.copyTo(tree);
        }
        if (!Files.exists(tree.resolve("classes"))) {
            ProjectTree.copy(project, tree, Map.of());
            // The autograder's package brings the tree compiled; a project of one's own is compiled here.
            if (!PrecompiledTree.useFor(project, tree)) {
                CompileResult compiled = compile(tree);
                if (!compiled.ok()) {
                    throw new IllegalStateException("the instructor's tree does not compile:\n" + compiled.messages());
                }
                GradingClasses.prepare(tree, classpath);
            }
        }
        return tree;
    }

    /** Every graded test (of one task, or all), failed with the same reason: listed from the instructor's own tree. */
    private List<TestOutcome> allFailed(Integer task, String why) throws IOException, InterruptedException {
        List<TestOutcome> failed = new ArrayList<>();
        for (TestOutcome t : listedTests(task)) {
            failed.add(t.failedWith(why));
        }
        return failed;
    }

    private CompileResult compile(Path tree) throws IOException {
        return ProjectCompiler.compile(tree, tree.resolve("classes"), classpath);
    }

    private TestProcess tests(Path tree) {
        return new TestProcess(tree, tree.resolve("classes"), classpath, tree.resolve("test-run"));
    }

    private static void describe(Submission s, StringBuilder output) {
        output.append("Graded files: ").append(s.files.isEmpty() ? "none" : String.join(", ", s.files.keySet())).append('\n');
        if (s.manifest != null) {
            output.append(SubmissionManifest.check(s.manifest, s.files));
        }
        if (!s.missing.isEmpty()) {
            output.append("Not found in the submission (graded as the untouched handout): ")
                    .append(String.join(", ", s.missing)).append('\n');
        }
        if (!s.ignored.isEmpty()) {
            int shown = Math.min(s.ignored.size(), 5);
            output.append("Ignored ").append(s.ignored.size()).append(s.ignored.size() == 1 ? " file" : " files")
                    .append(" (only the files you were asked to edit are graded): ")
                    .append(String.join(", ", s.ignored.subList(0, shown)))
                    .append(s.ignored.size() > shown ? " and " + (s.ignored.size() - shown) + " more" : "").append('\n');
        }
    }
}
