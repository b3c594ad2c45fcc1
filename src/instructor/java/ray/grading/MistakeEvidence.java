package ray.grading;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import ray.grading.VariantFolders.Variant;

/**
 * What each known mistake does, measured by running it: its renders of scenes (PNG bytes) and the
 * unit tests of its task it fails, with their messages. {@link VariantMistakes} compares a student's
 * results with these before it names a mistake. A mistake does the same whatever the submission, so
 * gradeAll keeps one of these for the whole class ({@link CompiledTree}) and each mistake renders a
 * scene, and runs its tests, once; and being in memory, no student code can touch them.
 */
final class MistakeEvidence {
    /** The renders of one scene by all of a task's known mistakes take seconds; this is the backstop. */
    private static final int RENDER_LIMIT_SECONDS = 120;

    /** Mistake folder name → scene file → its render (empty: the mistake rendered no picture of it). */
    private final Map<String, Map<String, Optional<byte[]>>> renders = new ConcurrentHashMap<>();
    /** Mistake folder name → its failed unit tests ({@link FailureSignatures#of}), once they ran. */
    private final Map<String, Map<String, String>> failures = new ConcurrentHashMap<>();
    /** One lock per mistake: gradings (and one grading's threads) run different mistakes' tests at once. */
    private final Map<String, Object> testLocks = new ConcurrentHashMap<>();
    /** Where the mistakes run (a compiled tree: its classes, handout and stand-ins), and its libraries; null: the grading's own tree. */
    private final Path home;
    private final String homeLibraries;

    /** Evidence for one grading, made in its own tree. */
    MistakeEvidence() {
        this(null, null);
    }

    /**
     * Evidence shared by gradings, made in {@code home} (a compiled instructor tree that no student
     * code runs in) with {@code libraries}, never in a grading's tree.
     */
    MistakeEvidence(Path home, String libraries) {
        this.home = home;
        this.homeLibraries = libraries;
    }

    /**
     * {@code mistake}'s renders of {@code scenes} (scene file → PNG bytes; a scene it could not render
     * is left out), rendering in {@code out} those not made yet. One mistake renders for one grading at
     * a time: another grading that needs it waits, then finds the renders made.
     */
    Map<String, byte[]> renders(Path tree, Variant mistake, List<String> scenes, String classpath, Path out)
            throws IOException, InterruptedException {
        Map<String, Optional<byte[]>> known = renders.computeIfAbsent(key(mistake), k -> new LinkedHashMap<>());
        synchronized (known) {
            List<String> missing = scenes.stream().filter(scene -> !known.containsKey(scene)).collect(Collectors.toList());
            Path made = missing.isEmpty() ? null : render(runIn(tree), mistake, missing, classpathOr(classpath), out);
            // When the render failed (no compile, out of time), nothing is kept: the next grading tries again.
            if (made != null) {
                for (String scene : missing) {
                    Path png = made.resolve(Path.of(scene).getFileName().toString().replaceFirst("\\.xml$", "") + ".png");
                    known.put(scene, Files.isRegularFile(png) ? Optional.of(Files.readAllBytes(png)) : Optional.empty());
                }
            }
            Map<String, byte[]> found = new LinkedHashMap<>();
            for (String scene : scenes) {
                known.getOrDefault(scene, Optional.empty()).ifPresent(bytes -> found.put(scene, bytes));
            }
            return found;
        }
    }

    /**
     * The regular unit tests of {@code mistake}'s task that it fails (test id → message, as
     * {@link FailureSignatures#of} keeps them), running them in {@code out} the first
     * time; empty when they could not run (no compile, out of time).
     */
    Optional<Map<String, String>> failedUnitTests(Path tree, Variant mistake, String libraries, Path out)
            throws IOException, InterruptedException {
        synchronized (testLocks.computeIfAbsent(key(mistake), k -> new Object())) {
            Map<String, String> known = failures.get(key(mistake));
            if (known != null) {
                return Optional.of(known);
            }
            Path runIn = runIn(tree);
            Path classes = compiled(mistake, runIn, out);
            Optional<Map<String, String>> ran = Optional.empty();
            if (classes != null) {
                // As a submission's code runs: in a worker, asked by the judge's stand-ins. The mistake is the
                // instructor's code, so its worker runs as the grader's user.
                try (Sandbox sandbox = Sandbox.create(GradingClasses.handout(runIn), false, 0)) {
                    Path workers = out.resolve("workers");
                    Files.createDirectories(workers);
                    sandbox.containment(classes, "mistake").write(workers.resolve("task-" + mistake.task));
                    ran = Optional.of(FailureSignatures.of(new TestProcess(runIn, runIn.resolve("classes"), classpathOr(libraries),
                            out.resolve("tests")).judging(GradingClasses.standIns(runIn), workers).withoutRenderTests()
                            .run(mistake.task)));
                } catch (IllegalStateException e) {
                    // The judge could not run them: no evidence, so no name from them.
                }
            }
            // When they could not run, nothing is kept: the next grading tries again.
            ran.ifPresent(signature -> failures.put(key(mistake), signature));
            return ran;
        }
    }

    private static String key(Variant mistake) {
        return mistake.folder.getFileName().toString();
    }

    private Path runIn(Path tree) {
        return home != null ? home : tree;
    }

    private String classpathOr(String libraries) {
        return home != null ? homeLibraries : libraries;
    }

    /**
     * The mistake as a submission: its files and the solution's of every other student file, compiled
     * (once) against the handout's framework of {@code tree}; null when they do not compile. The
     * worker runs a task's classes from these alone, so a file of the task that the mistake leaves out
     * (ClampTexture beside a wrong RepeatTexture) must be the solution's, not the handout's stub.
     */
    private static synchronized Path compiled(Variant mistake, Path tree, Path out) throws IOException {
        Path classes = out.resolve("classes");
        Path done = out.resolve("compiled");
        if (!Files.exists(done)) {
            Set<String> replaced = mistake.sources.stream().map(p -> p.getFileName().toString()).collect(Collectors.toSet());
            List<Path> sources = new ArrayList<>(mistake.sources);
            for (String file : StudentFiles.in(tree).keySet()) {
                if (!replaced.contains(Path.of(file).getFileName().toString())) {
                    sources.add(tree.resolve(file));
                }
            }
            if (!ProjectCompiler.compile(mistake.folder, sources, classes, GradingClasses.handout(tree).toString()).ok()) {
                return null;
            }
            Files.writeString(done, "");
        }
        return classes;
    }

    private static Path render(Path tree, Variant mistake, List<String> scenes, String libraries, Path out)
            throws IOException, InterruptedException {
        Path classes = compiled(mistake, tree, out);
        if (classes == null) {
            return null;
        }
        Path renders = out.resolve("renders");
        // The instructor's own mistake, rendered in one process: its classes before the tree's.
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx1g", "-Djava.awt.headless=true", "-cp", classes + File.pathSeparator + tree.resolve("classes") + File.pathSeparator + libraries,
                "ray.cli.Ray1", "render", "-o", renders.toString()));
        // A few scenes' renders: a short-lived JVM, like the tests'.
        command.addAll(1, TestProcess.SHORT_LIVED_JVM);
        command.addAll(scenes);
        Files.createDirectories(out);
        Process process = new ProcessBuilder(command).directory(tree.toFile()).redirectErrorStream(true)
                .redirectOutput(out.resolve("render.log").toFile()).start();
        if (!process.waitFor(RENDER_LIMIT_SECONDS, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            return null;
        }
        return renders;
    }
}
