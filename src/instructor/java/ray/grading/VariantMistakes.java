package ray.grading;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
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
            Path renders = render(tree, mistake, sceneFiles.values().stream().distinct().collect(Collectors.toList()), classpath, out);
            if (renders == null) {
                continue;
            }
            for (Map.Entry<String, Path> entry : yours.entrySet()) {
                String sceneName = Path.of(sceneFiles.get(entry.getKey())).getFileName().toString().replaceFirst("\\.xml$", "");
                Path theirs = renders.resolve(sceneName + ".png");
                if (Files.isRegularFile(theirs)) {
                    BufferedImage student = ImageIO.read(entry.getValue().toFile());
                    ImageDiff.Result diff = ImageDiff.compare(ImageIO.read(theirs.toFile()), student);
                    if (diff.passed() && diff.meanDifference() < closest.getOrDefault(entry.getKey(), Double.POSITIVE_INFINITY)) {
                        closest.put(entry.getKey(), diff.meanDifference());
                        names.put(entry.getKey(), MATCHES + mistake.knownWrong);
                    }
                }
            }
        }
        return names;
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
