package ray.grading;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import ray.grading.VariantFolders.Variant;
import ray.image.ImageDiff;

/**
 * Names a wrong render by the known mistake that makes the same image. The instructor's tree keeps
 * known-wrong versions of the student files (src/instructorTest/variants, each class saying
 * "Known wrong: what it does"); when a task's render tests fail, each known-wrong version of that
 * task renders the failing scenes with the solution for everything else, and a render that matches
 * the student's by the render tests' own comparison names the mistake ("Your render matches a known
 * mistake's, whose code takes the far root ..."), the closest one where several match. A correct
 * render matches the reference, and the known mistakes do not, so a correct submission never gets a
 * name.
 */
final class VariantMistakes {
    static final String MATCHES = "Your render matches a known mistake's, whose code ";
    /** The renders of one scene by all of a task's known mistakes take seconds; this is the backstop. */
    private static final int RENDER_LIMIT_SECONDS = 120;

    private VariantMistakes() {
    }

    /** The known mistakes of {@code task}, from the variants' own comments. */
    static List<Variant> of(Path tree, int task, Map<String, Integer> studentFiles) throws IOException {
        List<Variant> mistakes = new ArrayList<>();
        for (Variant variant : VariantFolders.in(tree, studentFiles)) {
            if (variant.task == task && variant.knownWrong != null) {
                mistakes.add(variant);
            }
        }
        return mistakes;
    }

    /**
     * For each of {@code failed} (a task's failed render tests, whose renders the test wrote into the
     * tree's render-diff report): the known mistake whose render matches the student's, by test id.
     *
     * @param classpath the instructor's classes and the libraries, for compiling and rendering the mistakes
     */
    static Map<String, String> named(Path tree, Path testsRanIn, List<TestOutcome> failed, List<Variant> mistakes, String classpath,
            Path work) throws IOException, InterruptedException {
        return named(tree, testsRanIn, failed, mistakes, classpath, work, new Renders());
    }

    /** The same, taking the mistakes' renders from {@code renders} and keeping the new ones there. */
    static Map<String, String> named(Path tree, Path testsRanIn, List<TestOutcome> failed, List<Variant> mistakes, String classpath,
            Path work, Renders renders) throws IOException, InterruptedException {
        Map<String, Path> yours = new LinkedHashMap<>();
        Map<String, String> sceneFiles = new LinkedHashMap<>();
        for (TestOutcome t : failed) {
            FailedRender render = FailedRender.of(t, testsRanIn);
            if (render != null) {
                yours.put(t.id(), render.yours);
                sceneFiles.put(t.id(), render.sceneFile);
            }
        }
        Map<String, String> names = new LinkedHashMap<>();
        if (yours.isEmpty()) {
            return names;
        }
        // Several mistakes may each match within the render tests' tolerance (two texture lookups a
        // texel apart in different ways both change a few edges); the closest render names it.
        Map<String, Double> closest = new LinkedHashMap<>();
        for (Variant mistake : mistakes) {
            Path out = work.resolve(mistake.folder.getFileName().toString());
            Map<String, byte[]> theirRenders = renders.of(tree, mistake,
                    sceneFiles.values().stream().distinct().collect(Collectors.toList()), classpath, out);
            for (Map.Entry<String, Path> entry : yours.entrySet()) {
                byte[] theirs = theirRenders.get(sceneFiles.get(entry.getKey()));
                if (theirs != null) {
                    BufferedImage student = ImageIO.read(entry.getValue().toFile());
                    ImageDiff.Result diff = ImageDiff.compare(ImageIO.read(new ByteArrayInputStream(theirs)), student);
                    if (diff.passed() && diff.meanDifference() < closest.getOrDefault(entry.getKey(), Double.POSITIVE_INFINITY)) {
                        closest.put(entry.getKey(), diff.meanDifference());
                        names.put(entry.getKey(), MATCHES + mistake.knownWrong);
                    }
                }
            }
        }
        return names;
    }

    /**
     * Known mistakes' renders, by mistake and scene file, as PNG files' bytes in memory. A mistake
     * renders a scene the same way whatever the submission, so gradeAll keeps one of these for the
     * whole class ({@link CompiledTree}) and each mistake renders each scene once, not once for
     * every submission with that scene wrong; and being in memory, no student code can touch them.
     */
    static final class Renders {
        /** Mistake folder name → scene file → its render (empty: the mistake rendered no picture of it). */
        private final Map<String, Map<String, Optional<byte[]>>> byMistake = new ConcurrentHashMap<>();
        /** Where the mistakes render, and the classes they render with; null: the grading's own tree. */
        private final Path home;
        private final String homeClasspath;

        /** Renders for one grading, made in its own tree. */
        Renders() {
            this(null, null);
        }

        /**
         * Renders shared by gradings, made in {@code home} (a compiled instructor tree that no student
         * code runs in) with {@code classpath} (its classes and the libraries), never in a grading's
         * tree, whose files that grading's code could have changed.
         */
        Renders(Path home, String classpath) {
            this.home = home;
            this.homeClasspath = classpath;
        }

        /**
         * {@code mistake}'s renders of {@code scenes} (scene file → PNG bytes; a scene it could not
         * render is left out), rendering in {@code out} those not made yet. One mistake renders for
         * one grading at a time: another grading that needs it waits, then finds the renders made.
         */
        Map<String, byte[]> of(Path tree, Variant mistake, List<String> scenes, String classpath, Path out)
                throws IOException, InterruptedException {
            Map<String, Optional<byte[]>> known = byMistake.computeIfAbsent(mistake.folder.getFileName().toString(),
                    k -> new LinkedHashMap<>());
            synchronized (known) {
                List<String> missing = scenes.stream().filter(scene -> !known.containsKey(scene)).collect(Collectors.toList());
                Path renders = missing.isEmpty() ? null
                        : home != null ? render(home, mistake, missing, homeClasspath, out) : render(tree, mistake, missing, classpath, out);
                // When the render failed (no compile, out of time), nothing is kept: the next grading tries again.
                if (renders != null) {
                    for (String scene : missing) {
                        Path png = renders.resolve(Path.of(scene).getFileName().toString().replaceFirst("\\.xml$", "") + ".png");
                        known.put(scene, Files.isRegularFile(png) ? Optional.of(Files.readAllBytes(png)) : Optional.empty());
                    }
                }
                Map<String, byte[]> found = new LinkedHashMap<>();
                for (String scene : scenes) {
                    Optional<byte[]> png = known.getOrDefault(scene, Optional.empty());
                    png.ifPresent(bytes -> found.put(scene, bytes));
                }
                return found;
            }
        }
    }

    /** The scenes rendered with the mistake's files in place of the solution's, or null when that fails. */
    private static Path render(Path tree, Variant mistake, List<String> scenes, String classpath, Path out)
            throws IOException, InterruptedException {
        Path classes = out.resolve("classes");
        if (!ProjectCompiler.compile(mistake.folder, mistake.sources, classes, classpath).ok()) {
            return null;
        }
        Path renders = out.resolve("renders");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx1g", "-Djava.awt.headless=true", "-cp", classes + File.pathSeparator + classpath,
                "ray.cli.RayTracer", "render", "-o", renders.toString()));
        // A few scenes' renders: a short-lived JVM, like the tests'.
        command.addAll(1, TestProcess.SHORT_LIVED_JVM);
        command.addAll(scenes);
        Process process = new ProcessBuilder(command).directory(tree.toFile()).redirectErrorStream(true)
                .redirectOutput(out.resolve("render.log").toFile()).start();
        if (!process.waitFor(RENDER_LIMIT_SECONDS, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            return null;
        }
        return renders;
    }
}
