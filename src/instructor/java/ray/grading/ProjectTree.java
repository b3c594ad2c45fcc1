package ray.grading;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/** Copies of a project tree to grade in: the sources and scenes, with some student files laid over them. */
public final class ProjectTree {
    /**
     * What a test run needs from the project; build output, VCS data and docs are not copied.
     * settings.gradle is there because the tests know the project folder by it, beside scenes/
     * (ray.testing.ProjectFolder): without it no render test could find its scenes.
     */
    public static final List<String> PARTS = List.of("src", "scenes", "settings.gradle", ray.assignment.Assignment.PROJECT_FILE);
    /** What the tests of {@code assignment} need from the project: {@link #PARTS}, and scenes-2019 under 2019's conventions. */
    public static List<String> parts(ray.assignment.Assignment assignment) {
        if (!assignment.course().equals("2019")) {
            return PARTS;
        }
        List<String> parts = new java.util.ArrayList<>(PARTS);
        parts.add(1, ray.scene.SceneOptions.SCENES_2019);
        return List.copyOf(parts);
    }

    private ProjectTree() {
    }

    /**
     * A fresh copy of {@code project}'s sources and scenes at {@code target}, with {@code overlay}
     * (relative path → file) laid over it, and the assignment this process grades
     * ({@link ray.assignment.Assignment#current()}) as its assignment file, complete: the tree's tests
     * read it from the class path, so they number and count the tasks as the grader does.
     */
    static Path copy(Path project, Path target, Map<String, Path> overlay) throws IOException {
        deleteRecursively(target);
        Files.createDirectories(target);
        for (String part : parts(ray.assignment.Assignment.current())) {
            Path from = project.resolve(part);
            if (Files.isDirectory(from)) {
                copyRecursively(from, target.resolve(part));
            } else if (Files.isRegularFile(from)) {
                Files.copy(from, target.resolve(part), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        for (Map.Entry<String, Path> file : overlay.entrySet()) {
            Path destination = target.resolve(file.getKey());
            Files.createDirectories(destination.getParent());
            Files.copy(file.getValue(), destination, StandardCopyOption.REPLACE_EXISTING);
        }
        writeAssignment(target, ray.assignment.Assignment.current());
        return target;
    }

    /** Writes {@code assignment}, complete, as the assignment file of the tree at {@code tree}. */
    public static void writeAssignment(Path tree, ray.assignment.Assignment assignment) throws IOException {
        Files.writeString(tree.resolve(ray.assignment.Assignment.PROJECT_FILE),
                assignment.toFileText("The assignment this tree is graded as (written by the grader)."), java.nio.charset.StandardCharsets.UTF_8);
    }

    static void copyRecursively(Path from, Path to) throws IOException {
        Files.walkFileTree(from, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) throws IOException {
                Files.createDirectories(to.resolve(from.relativize(dir).toString()));
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                Files.copy(file, to.resolve(from.relativize(file).toString()), StandardCopyOption.REPLACE_EXISTING);
                return FileVisitResult.CONTINUE;
            }
        });
    }

    public static void deleteRecursively(Path path) throws IOException {
        if (!Files.exists(path)) {
            return;
        }
        try (Stream<Path> walk = Files.walk(path)) {
            for (Path p : (Iterable<Path>) walk.sorted(Comparator.reverseOrder())::iterator) {
                Files.delete(p);
            }
        }
    }
}
