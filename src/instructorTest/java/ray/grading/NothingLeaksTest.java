package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;

/**
 * Nothing of the grader's own files reaches a student: a submission whose group throws the text of
 * a hidden test as its exception's message, and whose sphere prints the solution's camera, gets
 * results that quote neither (the quotations are replaced), while its own failures still read as
 * failures. Plus {@link Redaction} on hand-made text.
 */
public class NothingLeaksTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    private static final String HIDDEN = "src/instructorTest/java/ray/hidden/GroupHiddenTest.java";
    private static final String GROUP = "src/main/java/ray/surface/Group.java";
    private static final String SPHERE = "src/main/java/ray/surface/Sphere.java";

    @Test
    public void aLineOfAHiddenTestIsRemovedAndAnOrdinaryMessageKept() {
        Redaction redaction = Redaction.of(PROJECT);
        String secret = "public class GroupHiddenTest {";
        assertEquals("expected a hit at t = 4; your intersect returned false\nboom: " + Redaction.REMOVED,
                redaction.redact("expected a hit at t = 4; your intersect returned false\nboom: " + secret));
        // A line the handout ships too is no secret.
        assertEquals("import ray.IntersectionRecord;", redaction.redact("import ray.IntersectionRecord;"));
    }

    @Test(timeout = 600_000)
    public void aSubmissionThatPrintsTheGradersFilesShowsNothingOfThem() throws Exception {
        Path submission = FOLDER.getRoot().toPath().resolve("submission");
        Files.createDirectories(submission);
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            String source = Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8);
            if (file.equals(GROUP)) {
                source = source.replace("Ray closestSoFar = ray.copy();", "if (surfaces.size() >= 0) { try { throw new IllegalStateException("
                        + "java.nio.file.Files.readString(java.nio.file.Path.of(\"" + PROJECT.toAbsolutePath().resolve(HIDDEN) + "\"))); }"
                        + " catch (java.io.IOException e) { throw new java.io.UncheckedIOException(e); } }\n"
                        + "        Ray closestSoFar = ray.copy();");
            } else if (file.equals(SPHERE)) {
                source = source.replace("Vec3 d = ray.direction;", "try { System.out.println(java.nio.file.Files.readString("
                        + "java.nio.file.Path.of(\"" + PROJECT.toAbsolutePath().resolve("src/main/java/ray/camera/PerspectiveCamera.java") + "\"))); }"
                        + " catch (java.io.IOException e) { }\n        Vec3 d = ray.direction;");
            }
            Files.writeString(submission.resolve(Path.of(file).getFileName().toString()), source, StandardCharsets.UTF_8);
        }
        Path out = FOLDER.getRoot().toPath().resolve("out");
        String libraries = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
                .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));
        // Without isolation (as an instructor's own `gradle grade` runs), so that the files can be read and
        // it is the redaction that keeps them out; isolated, they cannot be read at all (AdversarialSubmissionsTest).
        int status = new CommandLine(new Grader()).execute("--project", PROJECT.toString(), "--classpath", libraries,
                "--submission", submission.toString(), "--out", out.toString(), "--no-isolation");
        assertEquals(0, status);
        String results = Files.readString(out.resolve("results.json"), StandardCharsets.UTF_8);
        assertTrue("the group's failures are reported", results.contains("IllegalStateException"));
        assertTrue("the quoted lines are replaced", results.contains(Redaction.REMOVED));
        String shipped;
        try (Stream<Path> files = Stream.concat(Files.walk(PROJECT.resolve("src/test/java")), Files.walk(PROJECT.resolve("src/main/java")))) {
            shipped = files.filter(p -> p.toString().endsWith(".java")).map(NothingLeaksTest::read).collect(Collectors.joining("\n"));
        }
        int checked = 0;
        for (String line : Files.readAllLines(PROJECT.resolve(HIDDEN))) {
            String trimmed = line.strip();
            if (trimmed.length() >= 24 && trimmed.contains("(") && !shipped.contains(trimmed)) {
                checked++;
                assertFalse("the results quote the hidden test: " + trimmed, results.contains(trimmed.replace("\"", "\\\"")));
            }
        }
        assertTrue("checked " + checked + " of the hidden test's own lines", checked > 20);
        assertFalse("the solution's camera was printed", results.contains("u.times(s).plus(v.times(t)).minus(w.times(projDistance))"));
    }

    private static String read(Path file) {
        try {
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
