package ray.tools;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import ray.grading.SolutionMarkers;

/**
 * Builds the student handout ({@code gradle handout}): a complete Gradle project in
 * {@code build/handout/ray1/} and the same as {@code build/distributions/ray1-handout.zip}.
 *
 * <p>What goes in is listed, not what stays out: the build files, the shipped sources and tests,
 * the scenes with their reference renders, and the student docs. Java sources lose their solution
 * blocks and get their stubs ({@link SolutionMarkers}); README.md loses its instructor sections
 * ({@code <!-- BEGIN INSTRUCTOR -->} … {@code <!-- END INSTRUCTOR -->}). Left out: the instructor-only
 * packages {@code ray.grading} and {@code ray.tools}, src/instructorTest (hidden tests), CI files and
 * docs/instructor.md. The build fails if any solution marker survives.
 */
public final class Handout {
    /** Top-level files and folders that ship, relative to the project. */
    private static final List<String> SHIPPED = List.of("build.gradle", "settings.gradle", "gradle", ".gitignore",
            "README.md", "src/main", "src/test", "scenes", "docs");
    /** Paths (prefixes, '/'-separated) under the shipped folders that stay with the instructor. */
    private static final List<String> INSTRUCTOR_ONLY = List.of("src/main/java/ray/grading/", "src/main/java/ray/tools/",
            "docs/instructor.md");
    private static final Pattern INSTRUCTOR_SECTION = Pattern.compile(
            "<!-- BEGIN INSTRUCTOR -->.*?<!-- END INSTRUCTOR -->\\n?", Pattern.DOTALL);
    /** Text that must never reach a student. */
    private static final List<String> LEAKS = List.of("BEGIN SOLUTION", "END SOLUTION", "// STUB:", "BEGIN INSTRUCTOR");

    private Handout() {
    }

    public static void main(String[] args) throws IOException {
        Path project = Path.of(args.length > 0 ? args[0] : ".");
        Path folder = project.resolve("build/handout/ray1");
        Path zip = project.resolve("build/distributions/ray1-handout.zip");
        List<String> files = build(project, folder);
        zip(folder, zip);
        System.out.println("handout: " + files.size() + " files in " + folder + " and " + zip);
    }

    /** Writes the handout into {@code target} (emptied first) and returns its files' relative paths. */
    public static List<String> build(Path project, Path target) throws IOException {
        delete(target);
        List<String> written = new ArrayList<>();
        for (String part : SHIPPED) {
            Path from = project.resolve(part);
            if (!Files.exists(from)) {
                continue;
            }
            List<Path> files;
            try (Stream<Path> walk = Files.walk(from)) {
                files = walk.filter(Files::isRegularFile).sorted().collect(Collectors.toList());
            }
            for (Path file : files) {
                String relative = project.relativize(file).toString().replace('\\', '/');
                if (INSTRUCTOR_ONLY.stream().anyMatch(relative::startsWith)) {
                    continue;
                }
                Path destination = target.resolve(relative);
                Files.createDirectories(destination.getParent());
                if (relative.endsWith(".java")) {
                    String source = Files.readString(file, StandardCharsets.UTF_8);
                    Files.writeString(destination, SolutionMarkers.studentVersion(source, relative), StandardCharsets.UTF_8);
                } else if (relative.equals("README.md")) {
                    String readme = Files.readString(file, StandardCharsets.UTF_8);
                    Files.writeString(destination, INSTRUCTOR_SECTION.matcher(readme).replaceAll(""), StandardCharsets.UTF_8);
                } else {
                    Files.copy(file, destination);
                }
                written.add(relative);
            }
        }
        checkNoLeaks(target, written);
        return written;
    }

    private static void checkNoLeaks(Path target, List<String> files) throws IOException {
        for (String relative : files) {
            if (!(relative.endsWith(".java") || relative.endsWith(".md") || relative.endsWith(".gradle") || relative.endsWith(".xml"))) {
                continue;
            }
            String text = Files.readString(target.resolve(relative), StandardCharsets.UTF_8);
            for (String leak : LEAKS) {
                if (text.contains(leak)) {
                    throw new IllegalStateException("the handout's " + relative + " still contains \"" + leak + "\"");
                }
            }
        }
    }

    /** Zips {@code folder} so that the archive holds one top folder of the same name (ray1/...). */
    static void zip(Path folder, Path zip) throws IOException {
        Files.createDirectories(zip.toAbsolutePath().getParent());
        Path top = folder.getParent();
        List<Path> files;
        try (Stream<Path> walk = Files.walk(folder)) {
            files = walk.filter(Files::isRegularFile).sorted().collect(Collectors.toList());
        }
        Path temporary = Files.createTempFile(zip.toAbsolutePath().getParent(), ".handout", ".tmp");
        try (OutputStream out = Files.newOutputStream(temporary); ZipOutputStream entries = new ZipOutputStream(out)) {
            for (Path file : files) {
                entries.putNextEntry(new ZipEntry(top.relativize(file).toString().replace('\\', '/')));
                Files.copy(file, entries);
                entries.closeEntry();
            }
        }
        Files.move(temporary, zip, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }

    private static void delete(Path path) throws IOException {
        if (Files.exists(path)) {
            try (Stream<Path> walk = Files.walk(path)) {
                for (Path p : (Iterable<Path>) walk.sorted(Comparator.reverseOrder())::iterator) {
                    Files.delete(p);
                }
            }
        }
    }
}
