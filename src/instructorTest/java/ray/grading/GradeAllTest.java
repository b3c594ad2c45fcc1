package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;

/**
 * gradeAll on a small class in Gradescope's export layout: a full solution, a stubbed sphere and a
 * zip with a stubbed group, graded two at once into a gradebook and a report; a second run grades
 * nothing again.
 */
public class GradeAllTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));
    private static final String SPHERE = "src/main/java/ray/surface/Sphere.java";
    private static final String GROUP = "src/main/java/ray/surface/Group.java";

    /** Writes the export: submission_1 (full), submission_2 (stubbed sphere), submission_3.zip (stubbed group). */
    static void writeExport(Path dir) throws Exception {
        Files.createDirectories(dir);
        Files.writeString(dir.resolve(ClassSubmission.METADATA), String.join("\n",
                "submission_1:",
                "  :submitters:",
                "  - :name: Ada Lovelace",
                "    :sid: '101'",
                "    :email: ada@example.edu",
                "  :created_at: 2024-01-01 10:00:00.000000000 -08:00",
                "  :score: 0.0",
                "submission_2:",
                "  :submitters:",
                "  - :name: \"Hopper, Grace\"",
                "    :sid: '102'",
                "    :email: grace@example.edu",
                "submission_3:",
                "  :submitters:",
                "  - :name: Alan Turing",
                "    :sid: '103'",
                "    :email: alan@example.edu",
                "  - :name: Kurt Gödel",
                "    :sid: '104'",
                "    :email: kurt@example.edu",
                ""), StandardCharsets.UTF_8);
        try (OutputStream o = Files.newOutputStream(dir.resolve("submission_3.zip")); ZipOutputStream zip = new ZipOutputStream(o)) {
            for (String file : StudentFiles.in(PROJECT).keySet()) {
                write(dir.resolve("submission_1").resolve(file), source(file, null));
                write(dir.resolve("submission_2").resolve(file), source(file, SPHERE));
                zip.putNextEntry(new ZipEntry(file));
                zip.write(source(file, GROUP).getBytes(StandardCharsets.UTF_8));
                zip.closeEntry();
            }
        }
    }

    private static String source(String file, String stubbed) throws Exception {
        String source = Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8);
        return file.equals(stubbed) ? SolutionMarkers.studentVersion(source, file) : source;
    }

    private static void write(Path file, String text) throws Exception {
        Files.createDirectories(file.getParent());
        Files.writeString(file, text, StandardCharsets.UTF_8);
    }

    private static String gradeAll(Path dir, Path out, int jobs, int expectedStatus) {
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        GradeAll command = new GradeAll();
        command.log = new PrintStream(log, true, StandardCharsets.UTF_8);
        int status = new CommandLine(command).execute("--project", PROJECT.toString(), "--classpath", LIBRARIES,
                "--submissions", dir.toString(), "--out", out.toString(), "--jobs", String.valueOf(jobs));
        String text = log.toString(StandardCharsets.UTF_8);
        assertEquals(text, expectedStatus, status);
        return text;
    }

    @Test(timeout = 900_000)
    public void gradesAClassIntoAGradebookAndAReportAndResumes() throws Exception {
        Path dir = folder.getRoot().toPath().resolve("export");
        Path out = folder.getRoot().toPath().resolve("grades");
        writeExport(dir);
        long start = System.nanoTime();
        String log = gradeAll(dir, out, 2, 0);
        System.err.printf("gradeAll --jobs 2 on 3 submissions: %.1f s%n", (System.nanoTime() - start) / 1e9);
        assertTrue(log, log.contains("graded 3 / 3"));

        List<String> rows = Files.readAllLines(out.resolve("gradebook.csv"), StandardCharsets.UTF_8);
        assertEquals(rows.toString(), 4, rows.size());
        List<String> header = List.of(rows.get(0).split(","));
        assertEquals(List.of("id", "name", "email", "SID"), header.subList(0, 4));
        assertEquals(List.of("bonus", "total"), header.subList(header.size() - 2, header.size()));
        int task2 = header.indexOf("Task 2");
        int task4 = header.indexOf("Task 4");
        assertTrue(header.toString(), task2 > 0 && task4 > 0);
        GradedResult full = GradedResult.read(out.resolve("submission_1/results.json"));
        assertTrue("the solution scores its maximum and more", full.score() >= full.maxScore() && full.maxScore() > 0);
        assertTrue(rows.get(1), rows.get(1).startsWith("submission_1,Ada Lovelace,ada@example.edu,101,"));
        assertTrue(rows.get(1), rows.get(1).endsWith("," + Gradebook.number(full.score())));
        // The name has a comma, so it is quoted; its task 2 (the sphere) earns nothing.
        assertTrue(rows.get(2), rows.get(2).startsWith("submission_2,\"Hopper, Grace\",grace@example.edu,"));
        List<String> sphere = List.of(rows.get(2).replace("\"Hopper, Grace\"", "Hopper").split(","));
        assertEquals("0", sphere.get(task2));
        assertEquals(Gradebook.number(full.taskPoints().get(4)), sphere.get(task4));
        assertTrue(Double.parseDouble(sphere.get(sphere.size() - 1)) < full.score());
        List<String> group = List.of(rows.get(3).split(","));
        assertEquals(List.of("submission_3", "Alan Turing; Kurt Gödel", "alan@example.edu; kurt@example.edu", "103; 104"),
                group.subList(0, 4));
        assertEquals("a stubbed group loses task 4", "0", group.get(task4));
        assertEquals(Gradebook.number(full.taskPoints().get(2)), group.get(task2));

        // lms.csv: a row per student, the group's two students each with the group's total.
        List<String> lms = Files.readAllLines(out.resolve("lms.csv"), StandardCharsets.UTF_8);
        assertEquals(List.of("SID,name,email,total", "101,Ada Lovelace,ada@example.edu," + Gradebook.number(full.score())),
                lms.subList(0, 2));
        assertEquals(lms.toString(), 5, lms.size());
        assertTrue(lms.get(3), lms.get(3).startsWith("103,Alan Turing,alan@example.edu,"));
        assertEquals(lms.get(3).substring(lms.get(3).lastIndexOf(',')), lms.get(4).substring(lms.get(4).lastIndexOf(',')));

        String html = Files.readString(out.resolve("index.html"), StandardCharsets.UTF_8);
        assertTrue(html.contains("<h2 id=\"histogram\">") && html.contains("<h2 id=\"pass-rates\">"));
        assertTrue(html, html.contains("<a href=\"submission_3/results.json\">submission_3</a>"));
        assertTrue(html, html.contains("Hopper, Grace"));
        // The least passed tests come first: the sphere's and the group's (each passed by 2 of 3 at most).
        String table = html.substring(html.indexOf("id=\"pass-rates\""));
        int firstSphere = table.indexOf("Task 2 (");
        int firstFullyPassed = table.indexOf("3 / 3");
        assertTrue(table, firstSphere > 0 && firstFullyPassed > firstSphere);

        FileTime graded = Files.getLastModifiedTime(out.resolve("submission_2/results.json"));
        String again = gradeAll(dir, out, 2, 0);
        assertEquals(again, 3, again.lines().filter(l -> l.startsWith("skipped submission_")).count());
        assertEquals("nothing is graded again", graded, Files.getLastModifiedTime(out.resolve("submission_2/results.json")));
    }

    @Test
    public void aMissingOrEmptyFolderIsAOneLineError() throws Exception {
        Path empty = folder.newFolder("empty").toPath();
        String log = gradeAll(empty, folder.getRoot().toPath().resolve("out"), 1, 2);
        assertEquals("error: " + empty + " holds no submissions (subfolders or .zip files)\n", log);
        Path nowhere = folder.getRoot().toPath().resolve("nowhere");
        assertEquals("error: " + nowhere + " is not a folder of submissions\n",
                gradeAll(nowhere, folder.getRoot().toPath().resolve("out"), 1, 2));
    }
}
