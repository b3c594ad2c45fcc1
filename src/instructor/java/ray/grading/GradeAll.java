package ray.grading;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code gradle gradeAll -Psubmissions=DIR}: grades every submission in DIR (subfolders and .zip
 * files, or Gradescope's "Export Submissions" folder with its submission_metadata.yml), one per
 * core at once, into OUT/&lt;id&gt;/results.json (with the grader's log beside it), then writes
 * OUT/gradebook.csv, OUT/index.html and OUT/lms.csv (one row per student, by student ID, for a
 * learning management system's import) for the whole class. Each submission's grading time goes to
 * the log as it finishes and into index.html, and the last line sums up the run (how many, how
 * long, the median time a submission).
 *
 * <p>The instructor's tree is copied and compiled once for the run ({@link CompiledTree}), not once
 * per submission, and each grading runs on a copy of it: a snapshot, so that editing the project
 * while gradeAll runs changes no grade.
 *
 * <p>It resumes: a submission whose results.json is newer than the submission is not graded again,
 * so a run that was stopped, or one after a few late submissions were added, grades only what is new.
 */
@Command(name = "gradeAll", mixinStandardHelpOptions = true, description = "Grades every submission in a folder.")
public final class GradeAll implements Callable<Integer> {
    @Option(names = "--project", required = true, description = "The instructor's project folder.")
    Path project;

    @Option(names = "--classpath", required = true, description = "Libraries the tests need (JUnit, ...).")
    String classpath;

    @Option(names = "--submissions", required = true, description = "A folder of submissions (subfolders or .zip files).")
    Path submissions;

    @Option(names = "--out", description = "Where the results go (default: ${DEFAULT-VALUE}).")
    Path out = Path.of("build/gradeAll");

    // Every core: a grading spends much of its time starting test JVMs and waiting for them, so one
    // grading a core keeps the cores busy without more waiting than each grading alone.
    @Option(names = "--jobs", description = "Submissions graded at once (default: the number of cores).")
    int jobs = defaultJobs();

    @Option(names = "--lms-total", description = "lms.csv's total: ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE};"
            + " score = every point, bonus included; capped = at most the maximum; regular = without the bonus).")
    Gradebook.LmsTotal lmsTotal = Gradebook.LmsTotal.score;

    @Option(names = "--no-isolation", negatable = false, description = "Run student code as the grader's own user even as root.")
    boolean noIsolation;

    @Mixin
    AssignmentOptions assignment = new AssignmentOptions();

    /** Where the log and progress lines go (the original stderr, as System.err is routed per grader). */
    PrintStream log;

    public static void main(String[] args) {
        System.exit(new CommandLine(new GradeAll()).execute(args));
    }

    @Override
    public Integer call() throws Exception {
        // The assignment is the process's while this run lasts (a test may run several in one JVM).
        ray.assignment.Assignment before = ray.assignment.Assignment.current();
        try {
            return gradeAll();
        } finally {
            ray.assignment.Assignment.use(before);
        }
    }

    private Integer gradeAll() throws Exception {
        PrintStream err = ThreadOutput.install();
        if (log == null) {
            log = err;
        }
        List<ClassSubmission> all;
        try {
            if (jobs < 1) {
                throw new IllegalArgumentException("--jobs must be at least 1, not " + jobs);
            }
            // Every submission is graded as this assignment (the shared tree and each grader read it).
            ray.assignment.Assignment.use(assignment.resolve(project));
            all = ClassSubmission.in(submissions, out);
        } catch (IllegalArgumentException | ray.assignment.AssignmentException e) {
            log.println("error: " + e.getMessage());
            return 2;
        }
        Files.createDirectories(out);
        long start = System.nanoTime();
        // The instructor's tree is compiled once for the class (when there is anything to grade),
        // in a hidden folder of -Pout that the run removes; each grading copies it.
        trees = Files.createTempDirectory(out, ".instructor-");
        ExecutorService pool = GradingSlots.pool(jobs);
        List<Future<?>> running = new ArrayList<>();
        List<Double> seconds = Collections.synchronizedList(new ArrayList<>());
        try {
            long toGrade = 0;
            for (ClassSubmission s : all) {
                toGrade += upToDate(s) ? 0 : 1;
            }
            if (toGrade > 0) {
                long compiling = System.nanoTime();
                try {
                    tree = newTree();
                } catch (IllegalStateException e) {
                    log.println("error: " + e.getMessage());
                    return 1;
                }
                log.println("compiled the instructor's tree in " + Progress.seconds((System.nanoTime() - compiling) / 1e9)
                        + ", once for the " + toGrade + (toGrade == 1 ? " submission" : " submissions") + " to grade");
            }
            Progress progress = new Progress(log, System.console() != null && log == err, all.size());
            for (ClassSubmission s : all) {
                running.add(pool.submit(() -> {
                    if (upToDate(s)) {
                        log.println("skipped " + s.id() + ": " + results(s) + " is newer than the submission");
                        progress.skipped();
                    } else {
                        long started = System.nanoTime();
                        try {
                            gradeOnSharedTree(s);
                        } catch (Exception | Error e) {
                            // One submission's trouble (say, a full disk) is its row's 0, not the class's stack trace.
                            log.println("failed to grade " + s.id() + " (score 0): " + e);
                        }
                        double took = (System.nanoTime() - started) / 1e9;
                        seconds.add(took);
                        progress.graded(s.id(), took);
                    }
                    return null;
                }));
            }
            for (Future<?> f : running) {
                f.get();
            }
            progress.finish();
        } finally {
            pool.shutdownNow();
            pool.awaitTermination(1, TimeUnit.MINUTES);
            ProjectTree.deleteRecursively(trees);
        }
        Map<ClassSubmission, GradedResult> graded = new LinkedHashMap<>();
        for (ClassSubmission s : all) {
            graded.put(s, GradedResult.read(results(s)));
        }
        ReadableFiles.writeAtomically(out.resolve("gradebook.csv"), Gradebook.csv(graded));
        ReadableFiles.writeAtomically(out.resolve("index.html"), ClassReport.html(graded));
        ReadableFiles.writeAtomically(out.resolve("lms.csv"), Gradebook.lms(graded, lmsTotal));
        if (Gradebook.unnamed(graded) > 0) {
            log.println("lms.csv leaves out " + Gradebook.unnamed(graded) + " of " + graded.size()
                    + " submissions: no student is named for them (submission_metadata.yml); gradebook.csv has them");
        }
        log.println(summary(seconds, all.size() - seconds.size(), (System.nanoTime() - start) / 1e9, jobs)
                + ": " + out.resolve("gradebook.csv") + ", " + out.resolve("index.html") + ", " + out.resolve("lms.csv"));
        return 0;
    }

    /** The default of --jobs: one grading per core. */
    static int defaultJobs() {
        return Math.max(1, Runtime.getRuntime().availableProcessors());
    }

    /**
     * The closing line: "graded 80 submissions in 412.3 s (median 9.8 s a submission, 2 at once)",
     * then "; 3 skipped (already graded)" when some were; {@code seconds} holds each grading's time.
     */
    static String summary(List<Double> seconds, int skipped, double totalSeconds, int jobs) {
        StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "graded %d %s in %.1f s", seconds.size(),
                seconds.size() == 1 ? "submission" : "submissions", totalSeconds));
        if (!seconds.isEmpty()) {
            // No more at once than there were to grade.
            line.append(" (median ").append(Progress.seconds(median(seconds))).append(" a submission, ")
                    .append(Math.min(jobs, seconds.size())).append(" at once)");
        }
        if (skipped > 0) {
            line.append("; ").append(skipped).append(" skipped (already graded)");
        }
        return line.toString();
    }

    static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        Collections.sort(sorted);
        int n = sorted.size();
        return n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
    }

    private Path results(ClassSubmission s) {
        return out.resolve(s.id()).resolve("results.json");
    }

    private boolean upToDate(ClassSubmission s) throws IOException {
        Path results = results(s);
        return Files.isRegularFile(results) && Files.getLastModifiedTime(results).compareTo(s.lastModified()) > 0;
    }

    /** The compiled tree gradings copy now; a fresh one replaces it when it changed. */
    private CompiledTree tree;
    /** Where the compiled trees are, under -Pout. */
    private Path trees;
    private int treesBuilt;

    /** A new compiled tree of the project, under {@link #trees}. */
    private CompiledTree newTree() throws IOException {
        return CompiledTree.build(project, trees.resolve("tree-" + ++treesBuilt), classpath);
    }

    private synchronized CompiledTree currentTree() {
        return tree;
    }

    /** Once {@code changed} is found changed, the gradings that start from now on copy a fresh tree. */
    private synchronized void replace(CompiledTree changed) throws IOException {
        if (tree == changed) {
            tree = newTree();
        }
    }

    /**
     * Grades {@code s} on the shared compiled tree, and checks that the tree is still as it was
     * compiled. Student code can find it (and, running as the grader's user, write to it): when it
     * changed, by this submission's code or by one graded at the same time, this grading may have
     * used it changed, so it is graded again on a fresh tree, which every later grading uses too.
     */
    private void gradeOnSharedTree(ClassSubmission s) throws IOException {
        for (int attempt = 1; ; attempt++) {
            CompiledTree used = currentTree();
            grade(s, used);
            if (used.unchanged()) {
                return;
            }
            replace(used);
            if (attempt == 2) {
                log.println("warning: the compiled instructor tree changed again while " + s.id() + " was graded on a fresh copy:"
                        + " its results stand, but check them by hand (and this submission's code)");
                return;
            }
            log.println("warning: the compiled instructor tree changed while " + s.id() + " was graded (student code wrote to"
                    + " it: this submission's, or one graded at the same time); grading " + s.id() + " again on a fresh copy");
        }
    }

    /** One Grader, in this JVM, on a copy of {@code tree}, its console output routed to OUT/&lt;id&gt;/grader.log. */
    private void grade(ClassSubmission s, CompiledTree tree) throws IOException {
        Path folder = out.resolve(s.id());
        Files.createDirectories(folder);
        try (OutputStream graderLog = Files.newOutputStream(folder.resolve("grader.log"))) {
            ThreadOutput.route(graderLog);
            // A submission that cannot be graded still has a results.json (0 points and why): the Grader writes it.
            // Its project is the compiled tree: the student files, stubs and secrets as they were compiled.
            List<String> args = new ArrayList<>(List.of("--project", tree.root().toString(), "--classpath", classpath,
                    "--submission", s.path().toString(), "--out", folder.toString()));
            if (noIsolation) {
                args.add("--no-isolation");
            }
            int status = new CommandLine(new Grader(tree, GradingSlots.current())).execute(args.toArray(new String[0]));
            if (status != 0) {
                log.println("failed to grade " + s.id() + " (score 0): see " + folder.resolve("results.json"));
            }
        } finally {
            ThreadOutput.route(null);
        }
    }
}
