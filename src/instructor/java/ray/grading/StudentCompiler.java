package ray.grading;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * Compiles a submission's files, task by task, in a JVM of its own with a time limit: a file made to
 * keep the compiler busy (types whose inference explodes, constants without end) costs its tasks,
 * not the grade. The grader stays out of the compiler's way, and the compiler runs no code of the
 * submission (no annotation processing).
 *
 * <p>The child's arguments are files: one list per task of its output folder, class path and sources;
 * it writes each task's outcome beside its output folder.
 */
final class StudentCompiler {
    /** Seconds all of a submission's files may take to compile (a few seconds at most, usually one). */
    static final int LIMIT_SECONDS = 120;
    private static final String OUTCOME = ".outcome";

    private StudentCompiler() {
    }

    /** One task's compilation: its sources, where the classes go, the class path they compile against. */
    static final class Unit {
        final Path project;
        final List<Path> sources;
        final Path classes;
        final String classpath;

        Unit(Path project, List<Path> sources, Path classes, String classpath) {
            this.project = project;
            this.sources = sources;
            this.classes = classes;
            this.classpath = classpath;
        }
    }

    /**
     * Compiles every unit, in order, in a child JVM that may take until {@code deadline} (System.nanoTime)
     * and at most {@link #LIMIT_SECONDS}; a unit it did not finish did not compile, and says why.
     */
    static Map<Unit, CompileResult> compile(List<Unit> units, long deadline) throws IOException, InterruptedException {
        Map<Unit, CompileResult> results = new LinkedHashMap<>();
        if (units.isEmpty()) {
            return results;
        }
        Path plan = Files.createTempFile("ray1-compile-", ".txt");
        try {
            List<String> lines = new ArrayList<>();
            for (Unit u : units) {
                ProjectTree.deleteRecursively(u.classes);
                Files.deleteIfExists(outcome(u));
                lines.add("unit " + u.project);
                lines.add("classes " + u.classes);
                lines.add("classpath " + u.classpath);
                u.sources.forEach(s -> lines.add("source " + s));
            }
            Files.write(plan, lines, StandardCharsets.UTF_8);
            List<String> command = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx768m",
                    "-XX:+UseSerialGC", "-cp", ownClasses(), StudentCompiler.class.getName(), plan.toString());
            Process child = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
            long limit = Math.min(deadline - System.nanoTime(), TimeUnit.SECONDS.toNanos(LIMIT_SECONDS));
            if (!child.waitFor(Math.max(0, limit), TimeUnit.NANOSECONDS)) {
                child.destroyForcibly().waitFor();
            }
        } finally {
            Files.deleteIfExists(plan);
        }
        for (Unit u : units) {
            Path outcome = outcome(u);
            if (Files.isRegularFile(outcome)) {
                String text = Files.readString(outcome, StandardCharsets.UTF_8);
                results.put(u, new CompileResult(text.startsWith("ok\n"), text.substring(text.indexOf('\n') + 1)));
            } else {
                results.put(u, new CompileResult(false, "the compiler did not finish within " + LIMIT_SECONDS
                        + " s (or the grade's time limit): is something in these files made to keep it busy?\n"));
            }
        }
        return results;
    }

    private static Path outcome(Unit u) {
        return u.classes.resolveSibling(u.classes.getFileName() + OUTCOME);
    }

    /** Where the grader's own classes are: the child runs this class from there. */
    private static String ownClasses() throws IOException {
        try {
            return Path.of(StudentCompiler.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (URISyntaxException e) {
            throw new IOException(e);
        }
    }

    /** The child: compiles each unit of the plan file and writes its outcome ("ok" or "failed", then the messages). */
    public static void main(String[] args) throws IOException {
        List<String> lines = Files.readAllLines(Path.of(args[0]), StandardCharsets.UTF_8);
        List<Unit> units = new ArrayList<>();
        Path project = null;
        Path classes = null;
        String classpath = null;
        List<Path> sources = null;
        for (String line : lines) {
            int space = line.indexOf(' ');
            String key = line.substring(0, space);
            String value = line.substring(space + 1);
            switch (key) {
                case "unit":
                    if (project != null) {
                        units.add(new Unit(project, sources, classes, classpath));
                    }
                    project = Path.of(value);
                    sources = new ArrayList<>();
                    break;
                case "classes":
                    classes = Path.of(value);
                    break;
                case "classpath":
                    classpath = value;
                    break;
                default:
                    sources.add(Path.of(value));
            }
        }
        if (project != null) {
            units.add(new Unit(project, sources, classes, classpath));
        }
        for (Unit u : units) {
            CompileResult result = ProjectCompiler.compile(u.project, u.sources, u.classes, u.classpath);
            Files.writeString(outcome(u), (result.ok() ? "ok\n" : "failed\n") + result.messages(), StandardCharsets.UTF_8);
        }
        System.exit(0);
    }
}
