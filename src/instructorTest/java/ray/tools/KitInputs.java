package ray.tools;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import ray.grading.SolutionMarkers;
import ray.grading.StudentFiles;

/**
 * What the package tests need around a {@link GradingKit}: its inputs taken from the test's own
 * class path (as the gradle tasks pass theirs), and a submission to grade.
 */
final class KitInputs {
    /** The file whose student version (a stub) the test submissions hand in: Task 2 scores nothing. */
    static final String SPHERE = "src/main/java/ray/surface/Sphere.java";

    final List<Path> classes = new ArrayList<>();
    final List<Path> libraries = new ArrayList<>();

    /** The test class path's class folders (but the tests' own) and jars. */
    KitInputs() {
        for (String entry : System.getProperty("java.class.path").split(File.pathSeparator)) {
            Path path = Path.of(entry);
            if (entry.endsWith(".jar")) {
                libraries.add(path);
            } else if (Files.isDirectory(path) && !path.getFileName().toString().equals("test")) {
                classes.add(path);
            }
        }
    }

    /** Writes every student file of the solution into {@code folder}, flat as the platforms hand them in, with a stubbed sphere. */
    static void writeSubmissionWithStubbedSphere(Path folder) throws IOException {
        Files.createDirectories(folder);
        for (String file : StudentFiles.in(Path.of(".")).keySet()) {
            String source = Files.readString(Path.of(file), StandardCharsets.UTF_8);
            if (file.equals(SPHERE)) {
                source = SolutionMarkers.studentVersion(source, file);
            }
            Files.writeString(folder.resolve(Path.of(file).getFileName().toString()), source, StandardCharsets.UTF_8);
        }
    }

    /** Runs a package's entry script with bash as the platform would, with its root folder in {@code rootVariable}; its exit code. */
    static int runScript(Path script, String rootVariable, Path root, Path log) throws IOException, InterruptedException {
        ProcessBuilder run = new ProcessBuilder("bash", script.toString()).redirectErrorStream(true).redirectOutput(log.toFile());
        run.environment().put(rootVariable, root.toString());
        return run.start().waitFor();
    }
}
