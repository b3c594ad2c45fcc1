package ray.tools;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.List;
import java.util.Map;
import org.apache.commons.compress.archivers.zip.ZipArchiveEntry;
import org.apache.commons.compress.archivers.zip.ZipFile;
import ray.grading.SolutionMarkers;
import ray.grading.StudentFiles;

/**
 * What the package tests need around a {@link GradingKit}: its inputs taken from the test's own
 * class path (as the gradle tasks pass theirs), and a submission to grade.
 */
public final class KitInputs {
    /** The file whose student version (a stub) the test submissions hand in: Task 2 scores nothing. */
    static final String SPHERE = "src/main/java/ray/surface/Sphere.java";

    public final List<Path> classes = new ArrayList<>();
    public final List<Path> libraries = new ArrayList<>();

    /** The test class path's class folders (but the tests' own) and jars. */
    public KitInputs() {
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
        return runScript(script, Map.of(rootVariable, root.toString()), log);
    }

    /** Runs a package's entry script with bash as the platform would, with {@code environment} added to this one's; its exit code. */
    public static int runScript(Path script, Map<String, String> environment, Path log) throws IOException, InterruptedException {
        ProcessBuilder run = new ProcessBuilder("bash", script.toString()).redirectErrorStream(true).redirectOutput(log.toFile());
        run.environment().putAll(environment);
        return run.start().waitFor();
    }

    /** Unzips with each entry's Unix mode, as the platforms' unzip keeps it. */
    public static void unpack(Path zip, Path target) throws IOException {
        try (ZipFile file = ZipFile.builder().setPath(zip).get()) {
            Enumeration<ZipArchiveEntry> entries = file.getEntries();
            while (entries.hasMoreElements()) {
                ZipArchiveEntry entry = entries.nextElement();
                Path out = target.resolve(entry.getName());
                Files.createDirectories(out.getParent());
                try (InputStream in = file.getInputStream(entry)) {
                    Files.copy(in, out);
                }
                if (entry.getUnixMode() != 0) {
                    Files.setPosixFilePermissions(out, PosixFilePermissions.fromString(modeString(entry.getUnixMode() & 0777)));
                }
            }
        }
    }

    private static String modeString(int mode) {
        StringBuilder s = new StringBuilder();
        for (int shift = 6; shift >= 0; shift -= 3) {
            int bits = (mode >> shift) & 7;
            s.append((bits & 4) != 0 ? 'r' : '-').append((bits & 2) != 0 ? 'w' : '-').append((bits & 1) != 0 ? 'x' : '-');
        }
        return s.toString();
    }
}
