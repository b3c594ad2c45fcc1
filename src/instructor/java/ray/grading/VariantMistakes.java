package ray.grading;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import ray.image.ImageDiff;

/**
 * Names a wrong render by the known mistake that makes the same image. The instructor's tree keeps
 * known-wrong versions of the student files (src/instructorTest/variants, each class saying
 * "Known wrong: what it does"); when a task's render tests fail, each known-wrong version of that
 * task renders the failing scenes with the solution for everything else, and a render that matches
 * the student's by the render tests' own comparison names the mistake ("Your render matches a known
 * mistake's, whose code takes the far root ..."). A correct render matches the reference, and the known
 * mistakes do not, so a correct submission never gets a name.
 */
final class VariantMistakes {
    static final String VARIANTS = "src/instructorTest/variants";
    static final String MATCHES = "Your render matches a known mistake's, whose code ";
    private static final Pattern KNOWN_WRONG = Pattern.compile("Known wrong: (.*?)\\s*\\*/", Pattern.DOTALL);
    /** The renders of one scene by all of a task's known mistakes take seconds; this is the backstop. */
    private static final int RENDER_LIMIT_SECONDS = 120;

    private VariantMistakes() {
    }

    /** A known-wrong version of a task's files: its folder and what it does wrong. */
    static final class Mistake {
        final Path folder;
        final String description;

        Mistake(Path folder, String description) {
            this.folder = folder;
            this.description = description;
        }
    }

    /** The known mistakes of {@code task}, from the variants' own comments. */
    static List<Mistake> of(Path tree, int task, Map<String, Integer> studentFiles) throws IOException {
        Path root = tree.resolve(VARIANTS);
        List<Mistake> mistakes = new ArrayList<>();
        if (!Files.isDirectory(root)) {
            return mistakes;
        }
        try (Stream<Path> folders = Files.list(root)) {
            for (Path folder : folders.filter(Files::isDirectory).sorted().collect(Collectors.toList())) {
                String description = null;
                boolean ofTask = false;
                try (Stream<Path> walk = Files.walk(folder)) {
                    for (Path file : walk.filter(p -> p.toString().endsWith(".java")).collect(Collectors.toList())) {
                        String relative = "src/main/java/" + folder.relativize(file).toString().replace('\\', '/');
                        ofTask |= Integer.valueOf(task).equals(studentFiles.get(relative));
                        Matcher m = KNOWN_WRONG.matcher(Files.readString(file, StandardCharsets.UTF_8));
                        if (description == null && m.find()) {
                            description = m.group(1).replaceAll("\\s*\\n\\s*\\*?\\s*", " ");
                        }
                    }
                }
                if (ofTask && description != null) {
                    mistakes.add(new Mistake(folder, description));
                }
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
    static Map<String, String> named(Path tree, List<TestOutcome> failed, List<Mistake> mistakes, String classpath, Path work)
            throws IOException, InterruptedException {
        Map<String, Path> yours = new LinkedHashMap<>();
        Map<String, String> sceneFiles = new LinkedHashMap<>();
        for (TestOutcome t : failed) {
            FailedRender render = FailedRender.of(t, tree);
            if (render != null) {
                yours.put(t.id(), render.yours);
                sceneFiles.put(t.id(), render.sceneFile);
            }
        }
        Map<String, String> names = new LinkedHashMap<>();
        if (yours.isEmpty()) {
            return names;
        }
        for (Mistake mistake : mistakes) {
            Path out = work.resolve(mistake.folder.getFileName().toString());
            Path renders = render(tree, mistake, sceneFiles.values().stream().distinct().collect(Collectors.toList()), classpath, out);
            if (renders == null) {
                continue;
            }
            for (Map.Entry<String, Path> entry : yours.entrySet()) {
                String sceneName = Path.of(sceneFiles.get(entry.getKey())).getFileName().toString().replaceFirst("\\.xml$", "");
                Path theirs = renders.resolve(sceneName + ".png");
                if (!names.containsKey(entry.getKey()) && Files.isRegularFile(theirs)) {
                    BufferedImage student = ImageIO.read(entry.getValue().toFile());
                    if (ImageDiff.compare(ImageIO.read(theirs.toFile()), student).passed()) {
                        names.put(entry.getKey(), MATCHES + mistake.description);
                    }
                }
            }
        }
        return names;
    }

    /** The scenes rendered with the mistake's files in place of the solution's, or null when that fails. */
    private static Path render(Path tree, Mistake mistake, List<String> scenes, String classpath, Path out)
            throws IOException, InterruptedException {
        List<Path> sources;
        try (Stream<Path> walk = Files.walk(mistake.folder)) {
            sources = walk.filter(p -> p.toString().endsWith(".java")).collect(Collectors.toList());
        }
        Path classes = out.resolve("classes");
        if (!ProjectCompiler.compile(mistake.folder, sources, classes, classpath).ok()) {
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
