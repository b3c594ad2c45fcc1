package ray.tools;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.io.File;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import ray.grading.CompileResult;
import ray.grading.PrairieLearnResults.HiddenTests;
import ray.grading.ProjectCompiler;
import ray.grading.ProjectTree;
import ray.grading.StudentFiles;
import ray.grading.TestOutcome;
import ray.grading.TestProcess;

/**
 * {@code gradle prairielearn}: PrairieLearn's external grader as a Docker build context,
 * build/prairielearn/:
 * <ul>
 * <li>{@code Dockerfile}: a public JDK 17 image with {@code ray1-grader/} baked in at /ray1-grader;</li>
 * <li>{@code ray1-grader/run}: the entrypoint, grading /grade/student into
 *     /grade/results/results.json (the root from {@code GRADE_ROOT}, for tests) with the same grader
 *     as Gradescope's, in PrairieLearn's format;</li>
 * <li>{@code ray1-grader/ray1/} and {@code lib/}: the {@link GradingKit};</li>
 * <li>{@code info.json} and {@code README.md}: the question's externalGradingOptions and how to set it up,
 *     with the {@code <pl-file-upload>} line: the student files as {@code file-names}, but those of a
 *     task whose every graded test is a bonus test (the cylinder) as {@code optional-file-names},
 *     found by compiling the grading tree and listing its tests ({@link StudentFiles#optional});
 *     its {@code environment} sets {@code RAY1_HIDDEN_TESTS}, how the grader shows hidden tests
 *     ({@link PrairieLearnResults.HiddenTests}, {@code summary} unless {@code --hidden-tests} says otherwise).</li>
 * </ul>
 * Usage: {@code PrairieLearnBundle PROJECT FOLDER IMAGE [--hidden-tests summary|each] [--assignment PRESET|FILE] [--tasks ID,…] --classes DIR... --libraries JAR...}.
 */
public final class PrairieLearnBundle {
    private PrairieLearnBundle() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 3) {
            System.err.println("usage: PrairieLearnBundle PROJECT FOLDER IMAGE [--hidden-tests summary|each] --classes DIR... --libraries JAR...");
            System.exit(2);
        }
        HiddenTests hiddenTests = HiddenTests.summary;
        for (int i = 3; i + 1 < args.length && !args[i].equals("--classes") && !args[i].equals("--libraries"); i++) {
            if (args[i].equals("--hidden-tests")) {
                try {
                    hiddenTests = HiddenTests.valueOf(args[i + 1]);
                } catch (IllegalArgumentException e) {
                    System.err.println("error: --hidden-tests is summary or each, not " + args[i + 1]);
                    System.exit(2);
                }
            }
        }
        List<Path> classes = new ArrayList<>();
        List<Path> libraries = new ArrayList<>();
        GradingKit.parse(args, 3, classes, libraries);
        AssignmentArguments.use(Path.of(args[0]), args);
        Path folder = Path.of(args[1]);
        build(Path.of(args[0]), folder, args[2], hiddenTests, classes, libraries);
        System.out.println("prairielearn: " + folder + " (image " + args[2] + ", hidden tests: " + hiddenTests + "; see its README.md)");
    }

    /** Writes the folder afresh, hidden tests shown as a summary per task. */
    public static void build(Path project, Path folder, String image, List<Path> classes, List<Path> libraries) throws IOException {
        build(project, folder, image, HiddenTests.summary, classes, libraries);
    }

    /** Writes the folder afresh (an earlier build's files never linger in the image). */
    public static void build(Path project, Path folder, String image, HiddenTests hiddenTests, List<Path> classes,
            List<Path> libraries) throws IOException {
        if (Files.exists(folder)) {
            ProjectTree.deleteRecursively(folder);
        }
        GradingKit.Sink sink = (name, content, executable) -> {
            Path file = folder.resolve(name);
            Files.createDirectories(file.getParent());
            Files.write(file, content);
            if (Files.getFileAttributeView(file, PosixFileAttributeView.class) != null) {
                Files.setPosixFilePermissions(file, PosixFilePermissions.fromString(executable ? "rwxr-xr-x" : "rw-r--r--"));
            }
        };
        sink.put("Dockerfile", GradingKit.resource("prairielearn/Dockerfile"), false);
        sink.put("ray1-grader/run", GradingKit.resource("prairielearn/run"), true);
        GradingKit.write(sink, "ray1-grader/", project, classes, libraries);
        // The upload's files, from the grading tree as the image holds it: required, or optional when
        // their task is extra credit (every test of it a bonus test).
        Path tree = folder.resolve("ray1-grader/ray1");
        Map<String, Integer> studentFiles = StudentFiles.in(tree);
        Set<String> optional = StudentFiles.optional(studentFiles, gradedTests(tree, libraries));
        Set<String> required = new TreeSet<>(studentFiles.keySet());
        required.removeAll(optional);
        String[] names = {fileNames(required), fileNames(optional)};
        sink.put("info.json", filled("info.json", image, names, hiddenTests), false);
        sink.put("README.md", filled("README.md", image, names, hiddenTests), false);
    }

    /**
     * Every graded test of the tree, as the grader lists them (compiled into a folder of their own,
     * then listed in a test JVM without running): what decides which files are optional.
     */
    static List<TestOutcome> gradedTests(Path tree, List<Path> libraries) throws IOException {
        Path work = Files.createTempDirectory("ray1-prairielearn-");
        try {
            String classpath = libraries.stream().filter(l -> l.toString().endsWith(".jar")).map(Path::toString)
                    .collect(Collectors.joining(File.pathSeparator));
            CompileResult compiled = ProjectCompiler.compile(tree, work.resolve("classes"), classpath);
            if (!compiled.ok()) {
                throw new IllegalStateException("the grading tree does not compile:\n" + compiled.messages());
            }
            return new TestProcess(tree, work.resolve("classes"), classpath, work.resolve("list")).list(null);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while listing the graded tests", e);
        } finally {
            ProjectTree.deleteRecursively(work);
        }
    }

    /** The files' names as pl-file-upload takes them: "ClampTexture.java,Group.java,…", sorted, without folders. */
    private static String fileNames(Set<String> files) {
        return String.join(",", new TreeSet<>(files.stream().map(f -> Path.of(f).getFileName().toString()).toList()));
    }

    /**
     * A text resource with the image's name, the required student files' names, the optional ones'
     * attribute (none when there are none) and the hidden tests' setting filled in.
     */
    private static byte[] filled(String name, String image, String[] files, HiddenTests hiddenTests) throws IOException {
        String text = new String(GradingKit.resource("prairielearn/" + name), StandardCharsets.UTF_8);
        return text.replace("@IMAGE@", image).replace("@FILES@", files[0])
                .replace("@OPTIONAL_FILES@", files[1].isEmpty() ? "" : " optional-file-names=\"" + files[1] + "\"")
                .replace("@HIDDEN_TESTS@", hiddenTests.name())
                .getBytes(StandardCharsets.UTF_8);
    }
}
