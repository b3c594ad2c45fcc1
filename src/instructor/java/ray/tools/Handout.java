package ray.tools;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.apache.commons.compress.archivers.zip.ZipArchiveEntry;
import org.apache.commons.compress.archivers.zip.ZipArchiveOutputStream;
import ray.assignment.Assignment;
import ray.grading.ProjectTree;
import ray.grading.SolutionMarkers;
import ray.scene.SceneOptions;

/**
 * Builds the student handout ({@code gradle handout}): a complete Gradle project in
 * {@code build/handout/ray1/} and the same as {@code build/distributions/ray1-handout.zip}.
 *
 * <p>The handout is the project without its instructor part. That part is found by name: every
 * file or folder whose name starts with {@code instructor} (src/instructor, src/instructorTest,
 * src/instructorBench, gradle/instructor.gradle, docs/instructor.md), and every section of a text
 * file between a {@code BEGIN INSTRUCTOR} and an {@code END INSTRUCTOR} line (README.md's
 * instructor sections, build.gradle's line that applies the instructor's build). Java sources lose
 * their solution blocks and get their stubs ({@link SolutionMarkers}). What is not the kit at all
 * (version control, CI, build output, and any file git does not track) is not copied either. The
 * build fails if any marker survives.
 */
public final class Handout {
    /** Top-level folders that are not part of the kit: version control, CI, build and render output, editor settings. */
    private static final Set<String> NOT_THE_KIT = Set.of(".git", ".gradle", ".ci", "build", "out", ".idea", ".vscode");
    /** The first and last line of an instructor section: a Markdown or Gradle comment line. */
    private static final Pattern SECTION_BEGIN = Pattern.compile("\\s*(<!--|//)\\s*BEGIN INSTRUCTOR\\b.*");
    private static final Pattern SECTION_END = Pattern.compile("\\s*(<!--|//)\\s*END INSTRUCTOR\\b.*");
    /** Text that must never reach a student. */
    private static final List<String> LEAKS = List.of("BEGIN SOLUTION", "END SOLUTION", "// STUB:", "BEGIN INSTRUCTOR",
            "END INSTRUCTOR", "END TASK -->", "END IF -->", "<!-- task:",
            SolutionMarkers.HINTS.strip(), SolutionMarkers.END_HINTS);

    private Handout() {
    }

    /**
     * {@code Handout PROJECT [--assignment PRESET|FILE] [--tasks ID,ID,…] [--hints LEVEL]}: the handout of the
     * project's assignment, or of the one given for this run (see {@link Assignment#resolve}).
     */
    public static void main(String[] args) throws IOException {
        Path project = Path.of(args.length > 0 ? args[0] : ".");
        Assignment assignment = AssignmentArguments.use(project, args);
        Path folder = project.resolve("build/handout/ray1");
        Path zip = project.resolve("build/distributions/ray1-handout.zip");
        List<String> files = build(project, folder, assignment);
        zip(folder, zip);
        System.out.println("handout: " + files.size() + " files in " + folder + " and " + zip);
        System.out.println("  " + assignment.tasks().size() + " tasks: " + String.join(", ", assignment.tasks().stream()
                .map(t -> assignment.number(t.id()) + " " + t.id() + (assignment.isExtraCredit(t.id()) ? " (extra credit)" : "")
                        + ", hints: " + assignment.hints(t.id()).id())
                .toArray(String[]::new)));
    }

    /** Writes the handout of the project's own assignment into {@code target}; see {@link #build(Path, Path, Assignment)}. */
    public static List<String> build(Path project, Path target) throws IOException {
        return build(project, target, Assignment.resolve(project, null, Map.of()));
    }

    /**
     * Writes the handout of {@code assignment} into {@code target} (emptied first) and returns its
     * files' relative paths. A chosen task's files are stubbed, their TODO comments numbered as the
     * assignment numbers the task; a task the assignment leaves out ships solved and without its tests.
     */
    public static List<String> build(Path project, Path target, Assignment assignment) throws IOException {
        delete(target);
        List<String> written = new ArrayList<>();
        for (Path file : kitFiles(project)) {
            String relative = project.relativize(file).toString().replace('\\', '/');
            if (relative.equals(Assignment.PROJECT_FILE) || isTestOfUnchosenTask(relative, assignment)
                    || isOtherCoursesScene(relative, assignment)) {
                continue;
            }
            Path destination = target.resolve(relative);
            Files.createDirectories(destination.getParent());
            if (relative.endsWith(".java")) {
                String source = Files.readString(file, StandardCharsets.UTF_8);
                Files.writeString(destination, javaVersion(source, relative, assignment), StandardCharsets.UTF_8);
            } else if (relative.endsWith(".md")) {
                // The students' docs, numbered and cut for the assignment (AssignmentDocs).
                String text = withoutInstructorSections(Files.readString(file, StandardCharsets.UTF_8), relative);
                Files.writeString(destination, AssignmentDocs.compose(text, relative, assignment), StandardCharsets.UTF_8);
            } else if (relative.endsWith(".gradle")) {
                String text = Files.readString(file, StandardCharsets.UTF_8);
                Files.writeString(destination, withoutInstructorSections(text, relative), StandardCharsets.UTF_8);
            } else {
                // gradlew must stay executable (students run ./gradlew), so the copy keeps the mode.
                Files.copy(file, destination, StandardCopyOption.COPY_ATTRIBUTES);
            }
            written.add(relative);
        }
        // The assignment, complete, where the students' build and the framework read it.
        String assignmentFile = "src/main/resources/" + Assignment.RESOURCE;
        Path destination = target.resolve(assignmentFile);
        Files.createDirectories(destination.getParent());
        Files.writeString(destination, assignment.toFileText("The tasks of this assignment, in order: the first is Task 1."),
                StandardCharsets.UTF_8);
        written.add(assignmentFile);
        written.sort(null);
        checkNoLeaks(target, written);
        return written;
    }

    /** A Java file as it ships: a chosen task's file stubbed and numbered, an unchosen task's solved, any other without markers. */
    private static String javaVersion(String source, String relative, Assignment assignment) {
        return assignment.table().ofFile(relative)
                .map(task -> assignment.isChosen(task.id())
                        ? SolutionMarkers.studentVersion(source, relative, assignment.number(task.id()), assignment.hints(task.id()))
                        : SolutionMarkers.solvedVersion(source, relative))
                .orElseGet(() -> SolutionMarkers.studentVersion(source, relative));
    }

    /** Whether {@code relative} is a test class (under src/test/java) of a task the assignment leaves out. */
    static boolean isTestOfUnchosenTask(String relative, Assignment assignment) {
        String prefix = "src/test/java/";
        if (!relative.startsWith(prefix) || !relative.endsWith(".java")) {
            return false;
        }
        String className = relative.substring(prefix.length(), relative.length() - ".java".length()).replace('/', '.');
        return assignment.table().ofTestClass(className).filter(t -> !assignment.isChosen(t.id())).isPresent();
    }

    /**
     * Every file of the project that ships, sorted: git's tracked files (every file when the project
     * is not a checkout), less the instructor part, version control, CI and build output.
     */
    private static List<Path> kitFiles(Path project) throws IOException {
        List<Path> files = new ArrayList<>();
        for (Path file : TrackedFiles.under(project, ".")) {
            Path relative = project.relativize(file);
            boolean ships = !NOT_THE_KIT.contains(relative.getName(0).toString());
            for (Path name : relative) {
                ships &= !isInstructorPart(name.toString());
            }
            if (ships) {
                files.add(file);
            }
        }
        return files;
    }

    /** Whether {@code relative} is a scene file (or reference) of a course other than the assignment's. */
    static boolean isOtherCoursesScene(String relative, Assignment assignment) {
        return relative.startsWith(SceneOptions.SCENES_2019 + "/") && !ProjectTree.parts(assignment).contains(SceneOptions.SCENES_2019);
    }

    /** Whether a file or folder of this name is the instructor's: its name starts with "instructor". */
    static boolean isInstructorPart(String name) {
        return name.startsWith("instructor");
    }

    /** {@code text} without its instructor sections (the BEGIN and END lines included). */
    static String withoutInstructorSections(String text, String fileName) {
        StringBuilder out = new StringBuilder(text.length());
        int beganAt = 0;
        String[] lines = text.split("\n", -1);
        for (int n = 0; n < lines.length; n++) {
            String line = lines[n];
            if (beganAt == 0 && SECTION_BEGIN.matcher(line).matches()) {
                beganAt = n + 1;
            } else if (beganAt > 0) {
                if (SECTION_END.matcher(line).matches()) {
                    beganAt = 0;
                }
            } else {
                out.append(line);
                if (n < lines.length - 1) {
                    out.append('\n');
                }
            }
        }
        if (beganAt > 0) {
            throw new IllegalArgumentException(fileName + ":" + beganAt + ": BEGIN INSTRUCTOR is never ended");
        }
        return out.toString();
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

    /**
     * Zips {@code folder} so that the archive holds one top folder of the same name (ray1/...), each
     * file with its Unix mode (0755 for an executable such as gradlew, else 0644), which
     * java.util.zip cannot record: unzip and macOS's Archive Utility restore it, so {@code ./gradlew}
     * runs straight from the unpacked zip.
     */
    static void zip(Path folder, Path zip) throws IOException {
        Files.createDirectories(zip.toAbsolutePath().getParent());
        Path top = folder.getParent();
        List<Path> files;
        try (Stream<Path> walk = Files.walk(folder)) {
            files = walk.filter(Files::isRegularFile).sorted().collect(Collectors.toList());
        }
        Path temporary = Files.createTempFile(zip.toAbsolutePath().getParent(), ".handout", ".tmp");
        try (OutputStream out = Files.newOutputStream(temporary); ZipArchiveOutputStream entries = new ZipArchiveOutputStream(out)) {
            for (Path file : files) {
                ZipArchiveEntry entry = new ZipArchiveEntry(top.relativize(file).toString().replace('\\', '/'));
                entry.setUnixMode(Files.isExecutable(file) ? 0755 : 0644);
                entries.putArchiveEntry(entry);
                Files.copy(file, entries);
                entries.closeArchiveEntry();
            }
        }
        Files.move(temporary, zip, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        ray.grading.ReadableFiles.makeReadable(zip);
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
