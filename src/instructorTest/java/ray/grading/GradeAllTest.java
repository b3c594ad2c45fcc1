package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.Assume;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;

/**
 * gradeAll on a small class in Gradescope's export layout: a full solution, a stubbed sphere and a
 * zip with a stubbed group, graded one per core into a gradebook and a report, with each one's time;
 * a second run grades nothing again.
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

    /** Runs gradeAll; {@code jobs} null leaves --jobs to its default. */
    private static String gradeAll(Path dir, Path out, Integer jobs, int expectedStatus, String... options) {
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        GradeAll command = new GradeAll();
        command.log = new PrintStream(log, true, StandardCharsets.UTF_8);
        List<String> args = new ArrayList<>(List.of("--project", PROJECT.toString(), "--classpath", LIBRARIES,
                "--submissions", dir.toString(), "--out", out.toString()));
        if (jobs != null) {
            args.addAll(List.of("--jobs", String.valueOf(jobs)));
        }
        args.addAll(List.of(options));
        int status = new CommandLine(command).execute(args.toArray(new String[0]));
        String text = log.toString(StandardCharsets.UTF_8);
        assertEquals(text, expectedStatus, status);
        return text;
    }

    /** "graded 2 / 3: submission_1 in 9.8 s, ETA 10 s": each graded submission's id → its seconds, from the log. */
    private static Map<String, Double> gradingSeconds(String log) {
        Map<String, Double> seconds = new TreeMap<>();
        Matcher m = Pattern.compile("(?m)^graded \\d+ / \\d+: (\\S+) in (\\d+\\.\\d) s").matcher(log);
        while (m.find()) {
            assertEquals(log, null, seconds.put(m.group(1), Double.parseDouble(m.group(2))));
        }
        return seconds;
    }

    /** The closing line's numbers: submissions graded, total seconds, median seconds, how many at once (0 when not said). */
    private static double[] summary(String log) {
        Matcher m = Pattern.compile("(?m)^graded (\\d+) submissions? in (\\d+\\.\\d) s"
                + "(?: \\(median (\\d+\\.\\d) s a submission, (\\d+) at once\\))?").matcher(log);
        assertTrue(log, m.find());
        return new double[] {Integer.parseInt(m.group(1)), Double.parseDouble(m.group(2)),
            m.group(3) == null ? 0 : Double.parseDouble(m.group(3)), m.group(4) == null ? 0 : Integer.parseInt(m.group(4))};
    }

    @Test
    public void usesEveryCoreByDefaultAndSaysHowLongTheRunTook() {
        GradeAll command = new GradeAll();
        new CommandLine(command).parseArgs("--project", ".", "--classpath", "", "--submissions", "x");
        assertEquals(Runtime.getRuntime().availableProcessors(), command.jobs);
        assertEquals(1.5, GradeAll.median(List.of(4.0, 1.0, 2.0, 1.0)), 0);
        assertEquals("graded 3 submissions in 12.0 s (median 2.0 s a submission, 2 at once); 1 skipped (already graded)",
                GradeAll.summary(List.of(8.0, 2.0, 1.5), 1, 12, 2));
        assertEquals("graded 1 submission in 2.5 s (median 2.4 s a submission, 1 at once)",
                GradeAll.summary(List.of(2.4), 0, 2.5, 4));
        assertEquals("graded 0 submissions in 0.3 s; 5 skipped (already graded)", GradeAll.summary(List.of(), 5, 0.3, 2));
    }

    @Test(timeout = 900_000)
    public void gradesAClassIntoAGradebookAndAReportAndResumes() throws Exception {
        Path dir = folder.getRoot().toPath().resolve("export");
        Path out = folder.getRoot().toPath().resolve("grades");
        writeExport(dir);
        long start = System.nanoTime();
        String log = gradeAll(dir, out, null, 0);
        double wall = (System.nanoTime() - start) / 1e9;
        System.err.printf("gradeAll (default jobs) on 3 submissions: %.1f s%n", wall);
        assertTrue(log, log.contains("graded 3 / 3"));
        // Each submission's time is in its line, and the summary agrees with them.
        Map<String, Double> seconds = gradingSeconds(log);
        assertEquals(log, Set.of("submission_1", "submission_2", "submission_3"), seconds.keySet());
        seconds.values().forEach(t -> assertTrue(log, t > 0 && t <= wall));
        double[] summary = summary(log);
        assertEquals(log, 3, summary[0], 0);
        assertTrue(log, summary[1] >= Collections.max(seconds.values()) && summary[1] <= wall + 0.1);
        List<Double> sorted = new ArrayList<>(seconds.values());
        Collections.sort(sorted);
        assertEquals(log, sorted.get(1), summary[2], 0.051);
        assertEquals(log, Math.min(3, Runtime.getRuntime().availableProcessors()), summary[3], 0);
        // The instructor's tree was compiled once for all three, and is gone afterwards.
        assertEquals(log, 1, log.lines().filter(l -> l.startsWith("compiled the instructor's tree in ")).count());
        assertTrue(log, log.contains(", once for the 3 submissions to grade"));
        assertEquals(List.of(), leftOver(out));

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
        // Each submission's row ends with its grading's seconds, as its results.json says.
        for (String id : seconds.keySet()) {
            GradedResult r = GradedResult.read(out.resolve(id).resolve("results.json"));
            assertTrue(id + ": " + r.seconds(), r.seconds() > 0 && r.seconds() <= seconds.get(id) + 0.1);
            Matcher row = Pattern.compile(">" + id + "</a></td>.*<td class=\"seconds\">(\\d+\\.\\d)</td></tr>").matcher(html);
            assertTrue(html, row.find());
            assertEquals(r.seconds(), Double.parseDouble(row.group(1)), 0.051);
        }

        FileTime graded = Files.getLastModifiedTime(out.resolve("submission_2/results.json"));
        String again = gradeAll(dir, out, 2, 0);
        assertEquals(again, 3, again.lines().filter(l -> l.startsWith("skipped submission_")).count());
        assertEquals(again, Map.of(), gradingSeconds(again));
        assertTrue("nothing to grade, nothing to compile: " + again, !again.contains("compiled the instructor's tree"));
        assertEquals(again, 0, summary(again)[0], 0);
        assertTrue(again, again.contains("; 3 skipped (already graded)"));
        assertEquals("nothing is graded again", graded, Files.getLastModifiedTime(out.resolve("submission_2/results.json")));
    }

    /** What a run left in its output folder besides the submissions' folders and the reports: hidden folders. */
    private static List<String> leftOver(Path out) throws Exception {
        try (Stream<Path> list = Files.list(out)) {
            return list.map(p -> p.getFileName().toString()).filter(n -> n.startsWith(".")).sorted().collect(Collectors.toList());
        }
    }

    /**
     * Code that writes garbage over every Group.class in gradeAll's compiled instructor trees under
     * {@code out} (which, left there, would fail the next submission's render tests), then notes
     * what it wrote in OUT/tampered.txt. The test tells it where {@code out} is; real code would
     * search the disk.
     */
    private static String tamper(Path out) {
        String folder = out.toAbsolutePath().toString().replace("\\", "\\\\");
        return String.join("\n",
                "    static {",
                "        try {",
                "            java.nio.file.Path out = java.nio.file.Path.of(\"" + folder + "\");",
                "            StringBuilder wrote = new StringBuilder();",
                "            try (java.util.stream.Stream<java.nio.file.Path> walk = java.nio.file.Files.walk(out)) {",
                "                for (java.nio.file.Path p : (Iterable<java.nio.file.Path>) walk::iterator) {",
                "                    if (p.toString().contains(\".instructor-\") && p.getFileName().toString().equals(\"Group.class\")) {",
                "                        java.nio.file.Files.writeString(p, \"not a class\");",
                "                        wrote.append(p).append('\\n');",
                "                    }",
                "                }",
                "            }",
                "            java.nio.file.Files.writeString(out.resolve(\"tampered.txt\"), wrote, java.nio.file.StandardOpenOption.CREATE,",
                "                    java.nio.file.StandardOpenOption.APPEND);",
                "        } catch (Exception | Error e) {",
                "            // Not allowed to: so much the better.",
                "        }",
                "    }",
                "");
    }

    /** A class of submission_a, whose Sphere writes over the compiled tree, and submission_b, the solution. */
    private static void writeTamperingClass(Path dir, Path out) throws Exception {
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            String solution = source(file, null);
            write(dir.resolve("submission_b").resolve(file), solution);
            write(dir.resolve("submission_a").resolve(file), !file.equals(SPHERE) ? solution
                    : solution.replaceFirst("(public class Sphere [^{]*\\{\n)", "$1" + Matcher.quoteReplacement(tamper(out))));
        }
        assertTrue(Files.readString(dir.resolve("submission_a").resolve(SPHERE)).contains("tampered.txt"));
    }

    /**
     * A submission whose code writes over the shared compiled tree (which it can when it runs as
     * the grader's user: without root, or with --no-isolation) costs the next submission nothing:
     * gradeAll notices the change, grades the culprit again on a fresh tree, and the next
     * submission gets a fresh tree too. (With the check turned off, the next one loses 12 points.)
     */
    @Test(timeout = 900_000)
    public void aSubmissionThatWritesOverTheSharedTreeChangesNoOtherGrade() throws Exception {
        Path dir = folder.getRoot().toPath().resolve("class");
        Path out = folder.getRoot().toPath().resolve("grades");
        writeTamperingClass(dir, out);
        String log = gradeAll(dir, out, 1, 0, "--no-isolation");
        Path tampered = out.resolve("tampered.txt");
        assertTrue("the tampering code ran and wrote: " + log, Files.exists(tampered));
        System.err.println("the tampering submission wrote over the shared tree:\n" + Files.readString(tampered));
        assertTrue(Files.readString(tampered), Files.readString(tampered).contains("Group.class"));
        // Noticed after each of its two gradings, and never after the correct submission's.
        assertTrue(log, log.contains("warning: the compiled instructor tree changed while submission_a was graded"));
        assertTrue(log, log.contains("warning: the compiled instructor tree changed again while submission_a was graded"));
        assertEquals(log, 2, log.lines().filter(l -> l.startsWith("warning: the compiled instructor tree changed")).count());
        GradedResult tampering = GradedResult.read(out.resolve("submission_a/results.json"));
        GradedResult next = GradedResult.read(out.resolve("submission_b/results.json"));
        assertTrue(log + next, next.score() >= next.maxScore() && next.maxScore() > 0);
        assertEquals(log, tampering.maxScore(), next.maxScore(), 0);
        assertEquals(List.of(), leftOver(out));
    }

    /** Isolated (as root, with the user ray1-student), the same code cannot write to the tree at all. */
    @Test(timeout = 900_000)
    public void aSubmissionRunAsItsOwnUserCannotWriteTheSharedTree() throws Exception {
        Assume.assumeTrue("student code runs isolated only as root with the user " + Sandbox.USER,
                Sandbox.isRoot() && Sandbox.lookUp(Sandbox.USER).isPresent());
        Path dir = folder.getRoot().toPath().resolve("class");
        Path out = folder.getRoot().toPath().resolve("grades");
        writeTamperingClass(dir, out);
        // The tampering submission alone: its grade is the solution's, and the tree stayed as it was.
        ProjectTree.deleteRecursively(dir.resolve("submission_b"));
        String log = gradeAll(dir, out, 1, 0);
        assertFalse(log, Files.exists(out.resolve("tampered.txt")));
        assertFalse(log, log.contains("warning:"));
        GradedResult tampering = GradedResult.read(out.resolve("submission_a/results.json"));
        assertTrue(log + tampering, tampering.score() >= tampering.maxScore() && tampering.maxScore() > 0);
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
