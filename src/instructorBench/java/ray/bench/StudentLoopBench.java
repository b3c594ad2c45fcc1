package ray.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import ray.grading.StudentFiles;
import ray.tools.Handout;

/**
 * {@code gradle studentLoopBench}: how long a student waits per edit, measured as a student works.
 * Builds the handout into build/bench/student-loop/ray1, puts the solution's student files in, and
 * times whole Gradle commands (Debian's {@code gradle} on the PATH):
 * <ul>
 * <li>warm: with the project's daemon running, after an edit of one method body of Sphere.java (a
 * changed statement, so the class changes but not its API, as most edits do): {@code gradle test}
 * and {@code gradle test -Ptask=2}, each the median of several edits;</li>
 * <li>cold: the first {@code gradle test} of a freshly started daemon (a heap size no running daemon
 * has forces a new one), after the same kind of edit.</li>
 * </ul>
 * Writes the table to build/bench/student-loop.md. Run it on a quiet machine: the two cores are the
 * measurement.
 */
public final class StudentLoopBench {
    private static final String EDITED = "src/main/java/ray/surface/Sphere.java";
    private static final int WARM_RUNS = 7;
    private static final int COLD_RUNS = 3;

    private StudentLoopBench() {
    }

    public static void main(String[] args) throws Exception {
        Path project = Path.of(args[0]).toAbsolutePath();
        Path out = Path.of(args[1]).toAbsolutePath();
        Path handout = out.resolve("student-loop/ray1");
        Handout.build(project, handout);
        for (String file : StudentFiles.in(project).keySet()) {
            Files.copy(project.resolve(file), handout.resolve(file), StandardCopyOption.REPLACE_EXISTING);
        }
        Files.writeString(handout.resolve("gradle.properties"), "org.gradle.daemon.idletimeout=120000\n");
        String solution = Files.readString(handout.resolve(EDITED), StandardCharsets.UTF_8);
        Loop loop = new Loop(handout, solution);

        // Warm-up: the daemon, the dependencies' resolution and the first compile.
        loop.run("test");
        loop.run("test", "-Ptask=2");
        List<Double> whole = new ArrayList<>();
        List<Double> oneTask = new ArrayList<>();
        for (int i = 0; i < WARM_RUNS; i++) {
            loop.edit();
            whole.add(loop.run("test"));
            loop.edit();
            oneTask.add(loop.run("test", "-Ptask=2"));
        }
        List<Double> cold = new ArrayList<>();
        for (int i = 0; i < COLD_RUNS; i++) {
            loop.edit();
            // Gradle reuses a daemon whose heap size matches, whatever other options it was given.
            cold.add(loop.run("-Dorg.gradle.jvmargs=-Xmx" + (700 + i) + "m", "test"));
        }
        Files.writeString(handout.resolve(EDITED), solution, StandardCharsets.UTF_8);

        String table = "| after a one-method edit of Sphere.java | median | runs (s) |\n|---|---:|---|\n"
                + row("`gradle test`, daemon warm", whole)
                + row("`gradle test -Ptask=2`, daemon warm", oneTask)
                + row("`gradle test`, fresh daemon (cold)", cold);
        Files.createDirectories(out);
        Files.writeString(out.resolve("student-loop.md"), table, StandardCharsets.UTF_8);
        System.out.print(table);
    }

    private static String row(String what, List<Double> seconds) {
        List<Double> sorted = new ArrayList<>(seconds);
        Collections.sort(sorted);
        double median = sorted.get(sorted.size() / 2);
        StringBuilder runs = new StringBuilder();
        for (double s : seconds) {
            runs.append(runs.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.2f", s));
        }
        return String.format(Locale.ROOT, "| %s | %.2f s | %s |%n", what, median, runs);
    }

    /** The handout under test: edits Sphere.java and runs gradle there. */
    private static final class Loop {
        private final Path handout;
        private final String solution;
        private int edits;

        Loop(Path handout, String solution) {
            this.handout = handout;
            this.solution = solution;
        }

        /** A new statement at the top of intersect: the class's bytecode changes, its API does not. */
        void edit() throws IOException {
            edits++;
            String edited = solution.replaceFirst("(public boolean intersect\\([^)]*\\) \\{)",
                    "$1\n        double edit" + edits + " = " + edits + ".0;");
            if (edited.equals(solution)) {
                throw new IllegalStateException("no intersect method to edit in " + EDITED);
            }
            Files.writeString(handout.resolve(EDITED), edited, StandardCharsets.UTF_8);
        }

        /** Seconds `gradle ARGS` took; its output goes to a log beside the handout. */
        double run(String... args) throws IOException, InterruptedException {
            List<String> command = new ArrayList<>(List.of("gradle", "--offline", "-q"));
            command.addAll(List.of(args));
            Path log = handout.resolveSibling("gradle.log");
            long start = System.nanoTime();
            Process p = new ProcessBuilder(command).directory(handout.toFile()).redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile())).start();
            if (!p.waitFor(10, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                throw new IllegalStateException("gradle " + String.join(" ", args) + " did not finish; see " + log);
            }
            double seconds = (System.nanoTime() - start) / 1e9;
            if (p.exitValue() != 0) {
                throw new IllegalStateException("gradle " + String.join(" ", args) + " failed with the solution; see " + log);
            }
            return seconds;
        }
    }
}
