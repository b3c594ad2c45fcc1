package ray.tools;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.apache.commons.compress.archivers.zip.ZipArchiveEntry;
import org.apache.commons.compress.archivers.zip.ZipArchiveOutputStream;
import ray.grading.ReadableFiles;

/**
 * {@code gradle autograder}: the Gradescope autograder as one zip, build/distributions/ray1-gradescope.zip.
 * <ul>
 * <li>{@code setup.sh}: installs Debian's JDK 17, the only thing the image needs;</li>
 * <li>{@code run_autograder}: grades /autograder/submission into /autograder/results/results.json
 *     (the root from {@code AUTOGRADER_ROOT}, for tests), by running the grader with java alone;</li>
 * <li>{@code ray1/}: the grading tree, the parts of the project the grader copies (its sources, with
 *     the solution the other tasks' tests run on, and the scenes with their references);</li>
 * <li>{@code lib/}: the grader and framework classes as one jar, and every library the grading needs,
 *     so that nothing is downloaded at grading time.</li>
 * </ul>
 * Usage: {@code AutograderBundle PROJECT ZIP [--assignment PRESET|FILE] [--tasks ID,…] --classes DIR... --libraries JAR...}.
 */
public final class AutograderBundle {
    /** The bundle's Unix modes: the scripts executable, the rest readable. */
    private static final int EXECUTABLE = 0100755;
    private static final int READABLE = 0100644;

    private AutograderBundle() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 2) {
            System.err.println("usage: AutograderBundle PROJECT ZIP --classes DIR... --libraries JAR...");
            System.exit(2);
        }
        List<Path> classes = new ArrayList<>();
        List<Path> libraries = new ArrayList<>();
        GradingKit.parse(args, 2, classes, libraries);
        AssignmentArguments.use(Path.of(args[0]), args);
        Path zip = Path.of(args[1]);
        build(Path.of(args[0]), zip, classes, libraries);
        System.out.println("autograder: " + zip + " (" + Files.size(zip) / 1024 + " KiB)");
    }

    /**
     * Writes the bundle.
     *
     * @param classes   folders of compiled classes (the framework's and the grader's), packed into lib/ray1-grader.jar
     * @param libraries jars the grader and the tests need (JUnit, ...), copied into lib/
     */
    public static void build(Path project, Path zip, List<Path> classes, List<Path> libraries) throws IOException {
        Files.createDirectories(zip.toAbsolutePath().getParent());
        Path temporary = Files.createTempFile(zip.toAbsolutePath().getParent(), ".gradescope", ".tmp");
        try (ZipArchiveOutputStream out = new ZipArchiveOutputStream(Files.newOutputStream(temporary))) {
            GradingKit.Sink sink = (name, content, executable) -> put(out, name, content, executable ? EXECUTABLE : READABLE);
            sink.put("setup.sh", GradingKit.resource("gradescope/setup.sh"), true);
            sink.put("run_autograder", GradingKit.resource("gradescope/run_autograder"), true);
            GradingKit.write(sink, "", project, classes, libraries);
        } catch (IOException | RuntimeException e) {
            Files.deleteIfExists(temporary);
            throw e;
        }
        Files.move(temporary, zip, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        ReadableFiles.makeReadable(zip);
    }

    private static void put(ZipArchiveOutputStream out, String name, byte[] content, int mode) throws IOException {
        ZipArchiveEntry entry = new ZipArchiveEntry(name);
        entry.setUnixMode(mode);
        out.putArchiveEntry(entry);
        out.write(content);
        out.closeArchiveEntry();
    }
}
