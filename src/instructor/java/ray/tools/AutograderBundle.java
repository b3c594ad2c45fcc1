package ray.tools;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.apache.commons.compress.archivers.zip.ZipArchiveEntry;
import org.apache.commons.compress.archivers.zip.ZipArchiveOutputStream;
import ray.grading.ProjectTree;
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
 * Usage: {@code AutograderBundle PROJECT ZIP --classes DIR... --libraries JAR...}.
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
        List<Path> current = null;
        for (int i = 2; i < args.length; i++) {
            if (args[i].equals("--classes")) {
                current = classes;
            } else if (args[i].equals("--libraries")) {
                current = libraries;
            } else if (current != null) {
                current.add(Path.of(args[i]));
            }
        }
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
            put(out, "setup.sh", script("setup.sh"), EXECUTABLE);
            put(out, "run_autograder", script("run_autograder"), EXECUTABLE);
            for (String part : ProjectTree.PARTS) {
                Path folder = project.resolve(part);
                if (!Files.isDirectory(folder)) {
                    continue;
                }
                try (Stream<Path> walk = Files.walk(folder)) {
                    for (Path file : walk.filter(Files::isRegularFile).sorted().collect(Collectors.toList())) {
                        put(out, "ray1/" + project.relativize(file).toString().replace('\\', '/'), Files.readAllBytes(file), READABLE);
                    }
                }
            }
            put(out, "lib/ray1-grader.jar", jarOf(classes), READABLE);
            for (Path library : libraries) {
                if (library.toString().endsWith(".jar")) {
                    put(out, "lib/" + library.getFileName(), Files.readAllBytes(library), READABLE);
                }
            }
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

    /** One jar of every class folder's files (the first folder's file wins a name clash). */
    private static byte[] jarOf(List<Path> folders) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        java.util.Set<String> seen = new java.util.HashSet<>();
        try (JarOutputStream jar = new JarOutputStream(bytes)) {
            for (Path folder : folders) {
                if (!Files.isDirectory(folder)) {
                    continue;
                }
                try (Stream<Path> walk = Files.walk(folder)) {
                    for (Path file : walk.filter(Files::isRegularFile).sorted().collect(Collectors.toList())) {
                        String name = folder.relativize(file).toString().replace('\\', '/');
                        if (seen.add(name)) {
                            jar.putNextEntry(new JarEntry(name));
                            Files.copy(file, jar);
                            jar.closeEntry();
                        }
                    }
                }
            }
        }
        return bytes.toByteArray();
    }

    /** A script of the bundle, kept as a resource beside this class. */
    private static byte[] script(String name) throws IOException {
        try (var in = AutograderBundle.class.getResourceAsStream("gradescope/" + name)) {
            if (in == null) {
                throw new IllegalStateException("the bundle's " + name + " is missing from the grader's resources");
            }
            return in.readAllBytes();
        }
    }
}
