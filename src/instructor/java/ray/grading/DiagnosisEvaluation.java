package ray.grading;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import ray.grading.VariantFolders.Variant;

/**
 * The evaluation of the grader's diagnosis ({@code gradle diagnosis}): every variant in the
 * instructor's tree, known-wrong and correct, and every held-out attempt (src/instructorTest/attempts)
 * is graded as a submission, and the table says for each whether the feedback named its mistake,
 * named a mistake it does not make, or named none; and for correct code, that nothing was named. A
 * known-wrong variant is graded on its own task (the other tasks would be the solution's); an
 * attempt, a whole submission, on all of them. The goal: every mistake named, no wrong name ever.
 */
@Command(name = "diagnosis", mixinStandardHelpOptions = true,
        description = "Grades every variant and held-out attempt and tabulates which mistakes the feedback names.")
public final class DiagnosisEvaluation implements Callable<Integer> {
    @Option(names = "--project", required = true, description = "The instructor's project folder.")
    Path project;

    @Option(names = "--classpath", required = true, description = "Libraries the tests need (JUnit, ...).")
    String classpath;

    @Option(names = "--out", description = "Work folder; diagnosis.md goes here (default: ${DEFAULT-VALUE}).")
    Path out = Path.of("build/diagnosis");

    @Option(names = "--jobs", description = "Submissions graded at once (default: the number of cores).")
    int jobs = Runtime.getRuntime().availableProcessors();

    @Option(names = "--no-isolation", negatable = false, description = "Run the code as the grader's own user even as root.")
    boolean noIsolation;

    public static void main(String[] args) {
        System.exit(new CommandLine(new DiagnosisEvaluation()).execute(args));
    }

    @Override
    public Integer call() throws Exception {
        List<DiagnosisRow> rows = evaluate();
        String table = DiagnosisRow.table(rows);
        Files.writeString(out.resolve("diagnosis.md"), table, StandardCharsets.UTF_8);
        System.out.print(table);
        System.out.println("table: " + out.resolve("diagnosis.md"));
        return 0;
    }

    /** Grades every case and judges what its feedback named. */
    List<DiagnosisRow> evaluate() throws IOException, InterruptedException {
        PrintStream console = ThreadOutput.install();
        Map<String, Integer> studentFiles = StudentFiles.in(project);
        List<Variant> variants = VariantFolders.in(project, studentFiles);
        Map<String, String> mistakeOf = new LinkedHashMap<>();
        for (Variant v : variants) {
            if (v.knownWrong != null) {
                mistakeOf.put(v.folder.getFileName().toString(), v.knownWrong);
            }
        }
        List<DiagnosisCase> cases = new ArrayList<>();
        for (Variant v : variants) {
            cases.add(DiagnosisCase.of(v));
        }
        cases.addAll(DiagnosisCase.attempts(project, mistakeOf.keySet()));

        Files.createDirectories(out);
        Path trees = Files.createTempDirectory(out, ".instructor-");
        CompiledTree tree = CompiledTree.build(project, trees.resolve("tree"), classpath);
        ExecutorService pool = GradingSlots.pool(Math.max(1, jobs));
        try {
            List<Future<DiagnosisRow>> rows = new ArrayList<>();
            for (DiagnosisCase c : cases) {
                rows.add(pool.submit(() -> {
                    DiagnosisRow row = c.judge(grade(c, tree, studentFiles.keySet()), mistakeOf);
                    console.println(row.summary());
                    return row;
                }));
            }
            List<DiagnosisRow> done = new ArrayList<>();
            for (Future<DiagnosisRow> row : rows) {
                done.add(row.get());
            }
            return done;
        } catch (java.util.concurrent.ExecutionException e) {
            throw new IOException("a grading failed: " + e.getCause(), e.getCause());
        } finally {
            pool.shutdownNow();
            ProjectTree.deleteRecursively(trees);
        }
    }

    /** {@code c} graded by the real grader on the shared compiled tree: its results.json. */
    private GradedFeedback grade(DiagnosisCase c, CompiledTree tree, Set<String> studentFiles) throws IOException {
        Path folder = out.resolve(c.name);
        ProjectTree.deleteRecursively(folder);
        Path submission = c.submissionIn(folder.resolve("submission"), tree.root(), studentFiles);
        List<String> args = new ArrayList<>(List.of("--project", tree.root().toString(), "--classpath", classpath,
                "--submission", submission.toString(), "--out", folder.toString()));
        if (c.task != null) {
            args.addAll(List.of("--task", c.task.toString()));
        }
        if (noIsolation) {
            args.add("--no-isolation");
        }
        try (OutputStream log = Files.newOutputStream(folder.resolve("grader.log"))) {
            ThreadOutput.route(log);
            new CommandLine(new Grader(tree, GradingSlots.current())).execute(args.toArray(new String[0]));
        } finally {
            ThreadOutput.route(null);
        }
        return GradedFeedback.read(folder.resolve("results.json"));
    }
}
