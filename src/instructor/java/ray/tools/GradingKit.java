package ray.tools;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import ray.assignment.Assignment;
import ray.grading.PrecompiledTree;
import ray.grading.ProjectTree;

/**
 * What every autograder package holds, whatever platform runs it: {@code ray1/}, the grading tree
 * (the parts of the project the grader copies: its sources, with the solution the other tasks' tests
 * run on, and the scenes with their references; git's tracked files only, see {@link TrackedFiles}),
 * and {@code lib/}, the grader and framework classes as one jar beside every library the grading
 * needs, so that nothing is downloaded at grading time.
 * The Gradescope zip and the PrairieLearn folder write the same kit through their own {@link Sink}.
 */
public final class GradingKit {
    /** Where a package's files go: a zip entry, a file in a folder. */
    public interface Sink {
        void put(String name, byte[] content, boolean executable) throws IOException;
    }

    private GradingKit() {
    }

    /**
     * Writes {@code prefix + "ray1/…"} and {@code prefix + "lib/…"}.
     *
     * @param classes   folders of compiled classes (the framework's and the grader's), packed into lib/ray1-grader.jar
     * @param libraries jars the grader and the tests need (JUnit, ...), copied into lib/
     */
    public static void write(Sink sink, String prefix, Path project, List<Path> classes, List<Path> libraries) throws IOException {
        // The tree as it ships, and (compiled from exactly that) its classes as the grader would compile them.
        Path tree = Files.createTempDirectory("ray1-kit-");
        try {
            for (String part : ProjectTree.parts(Assignment.current())) {
                if (part.equals(Assignment.PROJECT_FILE)) {
                    // The assignment the package grades, complete (AssignmentArguments), whatever the project's file says.
                    byte[] text = Assignment.current().toFileText("The assignment this package grades (written when it was packed).")
                            .getBytes(java.nio.charset.StandardCharsets.UTF_8);
                    sink.put(prefix + "ray1/" + part, text, false);
                    Files.write(tree.resolve(part), text);
                    continue;
                }
                // A folder (src, scenes) or a single file (settings.gradle).
                if (Files.exists(project.resolve(part))) {
                    for (Path file : TrackedFiles.under(project, part)) {
                        String name = slashed(project.relativize(file));
                        sink.put(prefix + "ray1/" + name, Files.readAllBytes(file), false);
                        Files.createDirectories(tree.resolve(name).getParent());
                        Files.copy(file, tree.resolve(name));
                    }
                }
            }
            PrecompiledTree.compile(tree, libraries.stream().map(Path::toString).collect(Collectors.joining(java.io.File.pathSeparator)));
            Path compiled = tree.resolve(PrecompiledTree.FOLDER);
            for (Path file : filesUnder(compiled)) {
                sink.put(prefix + "ray1/" + PrecompiledTree.FOLDER + "/" + slashed(compiled.relativize(file)), Files.readAllBytes(file), false);
            }
        } finally {
            ProjectTree.deleteRecursively(tree);
        }
        sink.put(prefix + "lib/ray1-grader.jar", jarOf(classes), false);
        for (Path library : libraries) {
            if (library.toString().endsWith(".jar")) {
                sink.put(prefix + "lib/" + library.getFileName(), Files.readAllBytes(library), false);
            }
        }
    }

    /**
     * Parses {@code --classes DIR... --libraries JAR...} from {@code args[from]} on, into the two
     * lists (both bundle mains take the same arguments as the gradle tasks pass them).
     */
    public static void parse(String[] args, int from, List<Path> classes, List<Path> libraries) {
        List<Path> current = null;
        for (int i = from; i < args.length; i++) {
            if (args[i].equals("--classes")) {
                current = classes;
            } else if (args[i].equals("--libraries")) {
                current = libraries;
            } else if (current != null) {
                current.add(Path.of(args[i]));
            }
        }
    }

    /** A script or text file kept as a resource beside this class (say "gradescope/setup.sh"). */
    public static byte[] resource(String name) throws IOException {
        try (var in = GradingKit.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("the package's " + name + " is missing from the grader's resources");
            }
            return in.readAllBytes();
        }
    }

    /** One jar of every class folder's files (the first folder's file wins a name clash). */
    private static byte[] jarOf(List<Path> folders) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        Set<String> seen = new HashSet<>();
        try (JarOutputStream jar = new JarOutputStream(bytes)) {
            for (Path folder : folders) {
                if (!Files.isDirectory(folder)) {
                    continue;
                }
                for (Path file : filesUnder(folder)) {
                    String name = slashed(folder.relativize(file));
                    // The assignment is the package tree's (ray1/assignment.properties), never the build's that packed it.
                    if (name.equals(Assignment.RESOURCE)) {
                        continue;
                    }
                    if (seen.add(name)) {
                        jar.putNextEntry(new JarEntry(name));
                        Files.copy(file, jar);
                        jar.closeEntry();
                    }
                }
            }
        }
        return bytes.toByteArray();
    }

    /** The folder's files in a fixed order, so two builds of one project write the same package. */
    private static List<Path> filesUnder(Path folder) throws IOException {
        try (Stream<Path> walk = Files.walk(folder)) {
            return walk.filter(Files::isRegularFile).sorted().collect(Collectors.toList());
        }
    }

    private static String slashed(Path relative) {
        return relative.toString().replace('\\', '/');
    }
}
