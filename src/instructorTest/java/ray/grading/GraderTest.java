package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.google.gson.Gson;
import java.io.File;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import picocli.CommandLine;

/**
 * The autograder on real submissions of the real assignment: a broken task costs exactly that
 * task's points (here a stubbed sphere and a group that calls System.exit), files that do not
 * belong are listed and ignored, and a submission that does not compile scores 0 with the
 * compiler's message.
 */
public class GraderTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".");
    private static final String LIBRARIES = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar")).collect(Collectors.joining(File.pathSeparator));
    private static final String SPHERE = "src/main/java/ray/surface/Sphere.java";
    private static final String GROUP = "src/main/java/ray/surface/Group.java";
    private static final String ORTHOGRAPHIC = "src/main/java/ray/camera/OrthographicCamera.java";
    private static final String TRIANGLE = "src/main/java/ray/surface/Triangle.java";

    @SuppressWarnings("unchecked")
    private static Map<String, Object> grade(Path submission, String name) throws Exception {
        Path out = FOLDER.getRoot().toPath().resolve("grade-" + name);
        int status = new CommandLine(new Grader()).execute("--project", PROJECT.toString(), "--classpath", LIBRARIES,
                "--submission", submission.toString(), "--out", out.toString());
        assertEquals(0, status);
        return new Gson().fromJson(Files.readString(out.resolve("results.json"), StandardCharsets.UTF_8), Map.class);
    }

    /**
     * Per task: regular points scored, regular points possible, bonus points scored, bonus tests
     * failed. Bonus tests (tagged "bonus") have their points as max_score and are counted apart.
     */
    @SuppressWarnings("unchecked")
    private static Map<Integer, double[]> pointsByTask(Map<String, Object> results) {
        Map<Integer, double[]> byTask = new java.util.TreeMap<>();
        for (Map<String, Object> t : (List<Map<String, Object>>) results.get("tests")) {
            int task = Integer.parseInt(((String) t.get("number")).split("\\.")[0]);
            double[] row = byTask.computeIfAbsent(task, k -> new double[4]);
            if (((List<String>) t.get("tags")).contains("bonus")) {
                assertTrue(t.get("name") + " is a bonus test out of its own points", (Double) t.get("max_score") > 0);
                row[2] += (Double) t.get("score");
                row[3] += "failed".equals(t.get("status")) ? 1 : 0;
            } else {
                row[0] += (Double) t.get("score");
                row[1] += (Double) t.get("max_score");
            }
        }
        return byTask;
    }

    /** A zip laid out like the handout under a top folder, with a stubbed sphere, an exiting group and junk. */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void eachBrokenTaskLosesExactlyItsOwnPoints() throws Exception {
        Path zip = FOLDER.getRoot().toPath().resolve("submission.zip");
        try (OutputStream o = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(o)) {
            for (String file : StudentFiles.in(PROJECT).keySet()) {
                String source = Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8);
                if (file.equals(SPHERE)) {
                    source = SolutionMarkers.studentVersion(source, file);
                } else if (file.equals(GROUP)) {
                    source = source.replace("Ray closestSoFar = ray.copy();", "System.exit(7);\n        Ray closestSoFar = ray.copy();");
                }
                put(z, "ray1/" + file, source);
            }
            put(z, "ray1/build.gradle", "this is not the instructor's build file");
            put(z, "ray1/src/test/java/ray/surface/SphereTest.java", "class SphereTest { /* a student's own edit */ }");
        }
        Map<String, Object> results = grade(zip, "broken");
        Map<Integer, double[]> byTask = pointsByTask(results);
        assertEquals("task 1 keeps all its points", byTask.get(1)[1], byTask.get(1)[0], 0);
        assertEquals("a stubbed sphere loses all of task 2", 0, byTask.get(2)[0], 0);
        assertEquals("a stubbed sphere earns no bonus", 0, byTask.get(2)[2], 0);
        assertEquals("task 3 keeps all its points", byTask.get(3)[1], byTask.get(3)[0], 0);
        assertTrue("task 3 has bonus tests", byTask.get(3)[2] > 0);
        assertEquals("task 3 (the solution) passes every bonus test", 0, byTask.get(3)[3], 0);
        assertEquals("an exiting group loses all of task 4", 0, byTask.get(4)[0], 0);
        double max = GradescopeResults.maxScore(results);
        double bonus = byTask.values().stream().mapToDouble(row -> row[2]).sum();
        // The score is what the regular tests of tasks 1 and 3 earn, plus every bonus point earned on top.
        assertEquals(max - byTask.get(2)[1] - byTask.get(4)[1] + bonus, (Double) results.get("score"), 1e-9);
        String output = (String) results.get("output");
        assertTrue(output, output.contains("Ignored 2 files (only the files you were asked to edit are graded): ray1/build.gradle, "
                + "ray1/src/test/java/ray/surface/SphereTest.java"));
        try (Stream<Path> left = Files.list(FOLDER.getRoot().toPath().resolve("grade-broken"))) {
            assertEquals("the run's work folder is removed", List.of("results.json"),
                    left.map(p -> p.getFileName().toString()).collect(Collectors.toList()));
        }
        assertTrue(results.toString(), results.toString().contains("called System.exit"));
        // The stubbed sphere's renders fail with their pictures inline and the trace of the worst pixel.
        Map<String, Object> render = ((List<Map<String, Object>>) results.get("tests")).stream()
                .filter(t -> ((String) t.get("name")).contains("SphereRenderTest.rendersLikeTheReference[one-sphere]"))
                .findFirst().orElseThrow();
        String page = (String) render.get("output");
        assertEquals("html", render.get("output_format"));
        assertEquals(page, 3, page.split("src=\"data:image/png;base64,", -1).length - 1);
        assertTrue(page, page.contains("gradle run --args=\"trace scenes/one-sphere.xml "));
        assertTrue(page, !page.contains("file://"));
    }

    /**
     * Flat files as Gradescope uploads them, one of which does not compile: that task scores 0 with the
     * compiler's message, and every other task is graded as usual (full marks here).
     */
    @Test(timeout = 600_000)
    public void aFileThatDoesNotCompileCostsOnlyItsOwnTask() throws Exception {
        Path flat = FOLDER.getRoot().toPath().resolve("flat");
        Files.createDirectories(flat);
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            String source = Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8);
            if (file.equals(SPHERE)) {
                source = source.replace("double halfB = f.dot(d);", "double halfB = f.dot(d)");
            }
            Files.writeString(flat.resolve(Path.of(file).getFileName().toString()), source, StandardCharsets.UTF_8);
        }
        Map<String, Object> results = grade(flat, "uncompilable");
        Map<Integer, double[]> byTask = pointsByTask(results);
        assertEquals("the sphere that does not compile loses all of task 2", 0, byTask.get(2)[0], 0);
        for (int task : new int[] {1, 3, 4, 5}) {
            assertEquals("task " + task + " keeps all its points", byTask.get(task)[1], byTask.get(task)[0], 0);
        }
        String output = (String) results.get("output");
        assertTrue(output, output.contains("Task 2's files (src/main/java/ray/surface/Sphere.java) do not compile"));
        assertTrue(output, output.contains("src/main/java/ray/surface/Sphere.java:") && output.contains("';' expected"));
        assertTrue(results.toString(), results.toString().contains("';' expected"));
    }

    /** Flat files as Gradescope uploads them: the solution's student files, with the known-wrong variant's in their place. */
    private static Path solutionWithVariant(String variant) throws Exception {
        Path flat = FOLDER.getRoot().toPath().resolve("submission-" + variant);
        Files.createDirectories(flat);
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            Files.copy(PROJECT.resolve(file), flat.resolve(Path.of(file).getFileName().toString()));
        }
        try (Stream<Path> files = Files.walk(Path.of("src/instructorTest/variants", variant))) {
            for (Path file : files.filter(p -> p.toString().endsWith(".java")).collect(Collectors.toList())) {
                Files.copy(file, flat.resolve(file.getFileName().toString()), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
        }
        return flat;
    }

    /** A sphere that takes the far root renders like the known mistake of that name: its render tests say so. */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void aFarRootSphereIsNamedInItsRenderTests() throws Exception {
        Map<String, Object> results = grade(solutionWithVariant("sphere-far-root"), "far-root");
        Map<String, Object> onesphere = ((List<Map<String, Object>>) results.get("tests")).stream()
                .filter(t -> ((String) t.get("name")).contains("SphereRenderTest.rendersLikeTheReference[one-sphere]"))
                .findFirst().orElseThrow();
        assertEquals("failed", onesphere.get("status"));
        assertTrue(onesphere.toString(), ((String) onesphere.get("output")).contains(
                "Your render matches a known mistake&#39;s, whose code takes the far root".replace("&#39;", "'")));
    }

    /** A camera that measures v from the top renders the reference upside down: its render tests say so. */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void aFlippedCameraIsNamedInItsRenderTests() throws Exception {
        Map<String, Object> results = grade(solutionWithVariant("camera-flipped-v"), "flipped");
        List<Map<String, Object>> renders = ((List<Map<String, Object>>) results.get("tests")).stream()
                .filter(t -> ((String) t.get("name")).contains("CameraRenderTest.")).collect(Collectors.toList());
        assertTrue("the camera's render tests ran", !renders.isEmpty());
        for (Map<String, Object> t : renders) {
            assertTrue(t.toString(), ((String) t.get("output")).contains("Your image matches the reference flipped upside down"));
        }
    }

    /**
     * When the grader itself cannot grade (the submission path does not exist), it still writes
     * results.json: 0 points and the reason, replacing whatever an earlier run left there, readable
     * by everyone, and exits 1.
     */
    @Test
    public void aGraderThatFailsWritesAResultOfZeroWithTheReason() throws Exception {
        Path out = FOLDER.getRoot().toPath().resolve("grade-missing");
        Files.createDirectories(out);
        Files.writeString(out.resolve("results.json"), "{\"score\": 99, \"tests\": []}");
        Path nowhere = FOLDER.getRoot().toPath().resolve("no-such-submission");
        int status = new CommandLine(new Grader()).execute("--project", PROJECT.toString(), "--classpath", LIBRARIES,
                "--submission", nowhere.toString(), "--out", out.toString());
        assertEquals(1, status);
        @SuppressWarnings("unchecked")
        Map<String, Object> results = new Gson().fromJson(Files.readString(out.resolve("results.json")), Map.class);
        assertEquals(0, (Double) results.get("score"), 0);
        assertEquals(List.of(), results.get("tests"));
        assertTrue(results.toString(), ((String) results.get("output")).startsWith("The autograder could not grade this submission: ")
                && ((String) results.get("output")).contains("no-such-submission"));
        assertEquals("rw-r--r--", java.nio.file.attribute.PosixFilePermissions.toString(
                Files.getPosixFilePermissions(out.resolve("results.json"))));
        try (Stream<Path> left = Files.list(out)) {
            assertEquals(List.of("results.json"), left.map(p -> p.getFileName().toString()).collect(Collectors.toList()));
        }
    }

    /**
     * A submission with a bug of each kind in the student's own code: an orthographic camera that
     * throws, a sphere that allocates without bound when the ray starts inside it, a triangle that
     * reports a hit at t = NaN for rays with a positive z direction, and a group that loops forever
     * when it is empty. (A System.exit is the test above.) Grading completes with a valid
     * results.json, each bug costs tests of its own task only, and each failure says what happened.
     */
    @Test(timeout = 1_800_000)
    @SuppressWarnings("unchecked")
    public void throwingLoopingHoardingAndNaNCodeCostsOnlyTheTestsThatReachIt() throws Exception {
        Path dir = FOLDER.getRoot().toPath().resolve("misbehaving");
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            String source = Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8);
            if (file.equals(ORTHOGRAPHIC)) {
                source = insertAfter(source, "// BEGIN SOLUTION\n",
                        "        if (imageU == imageU) {\n            throw new IllegalStateException(\"a student's bug\");\n        }\n");
            } else if (file.equals(SPHERE)) {
                source = insertAfter(source, "Vec3 f = ray.origin.minus(center);\n", "        if (f.dot(f) < radius * radius) {\n"
                        + "            java.util.List<long[]> hoard = new java.util.ArrayList<>();\n"
                        + "            while (true) {\n                hoard.add(new long[1 << 20]);\n            }\n        }\n");
            } else if (file.equals(TRIANGLE)) {
                source = insertAfter(source, "// BEGIN SOLUTION\n", "        if (ray.direction.z > 0) {\n"
                        + "            out.t = Double.NaN;\n            out.surface = this;\n            return true;\n        }\n");
            } else if (file.equals(GROUP)) {
                source = insertAfter(source, "// BEGIN SOLUTION\n", "        while (surfaces.isEmpty()) {\n"
                        + "            Thread.onSpinWait();\n        }\n");
            }
            Path copy = dir.resolve(file);
            Files.createDirectories(copy.getParent());
            Files.writeString(copy, source, StandardCharsets.UTF_8);
        }
        Map<String, Object> results = grade(dir, "misbehaving");

        double score = 0;
        Map<Integer, int[]> passedAndFailed = new java.util.TreeMap<>();
        Map<Integer, String> failures = new java.util.TreeMap<>();
        for (Map<String, Object> t : (List<Map<String, Object>>) results.get("tests")) {
            int task = Integer.parseInt(((String) t.get("number")).split("\\.")[0]);
            boolean passed = "passed".equals(t.get("status"));
            passedAndFailed.computeIfAbsent(task, k -> new int[2])[passed ? 0 : 1]++;
            if (!passed) {
                failures.merge(task, (String) t.get("output") + "\n", String::concat);
            }
            score += (Double) t.get("score");
        }
        assertEquals("the score is the sum of the tests' scores", score, (Double) results.get("score"), 1e-9);
        for (int task = 1; task <= 4; task++) {
            assertTrue("task " + task + " loses some tests: " + passedAndFailed, passedAndFailed.get(task)[1] > 0);
            assertTrue("task " + task + " keeps the tests its bug does not reach: " + passedAndFailed,
                    passedAndFailed.get(task)[0] > 0);
        }
        assertTrue(failures.get(1), failures.get(1).contains("your code threw java.lang.IllegalStateException: a student's bug"
                + " at OrthographicCamera.java:"));
        assertTrue(failures.get(2), failures.get(2).contains("your code ran out of memory (java.lang.OutOfMemoryError"));
        assertTrue(failures.get(3), failures.get(3).contains("NaN"));
        assertTrue(failures.get(4), failures.get(4).contains("took longer than 10 s: is there a loop that never ends?"));
        for (int task = 1; task <= 4; task++) {
            assertTrue("no other task's bug shows in task " + task, !failures.get(task).contains("[Task " + (task % 4 + 1)));
        }
    }

    /**
     * A sphere whose every exception carries 5.4 MB of text, on both platforms: each message is cut
     * with "… (cut)", results.json stays under 1 MB, and the grade is the same.
     */
    @Test(timeout = 1_800_000)
    @SuppressWarnings("unchecked")
    public void aSubmissionThatShoutsGetsAResultsFileUnderOneMegabyte() throws Exception {
        Path dir = FOLDER.getRoot().toPath().resolve("shouting");
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            String source = Files.readString(PROJECT.resolve(file), StandardCharsets.UTF_8);
            if (file.equals(SPHERE)) {
                source = insertAfter(source, "Vec3 f = ray.origin.minus(center);\n",
                        "        if (f != null) {\n            throw new IllegalStateException(\"shout \".repeat(900_000));\n        }\n");
            }
            Path copy = dir.resolve(file);
            Files.createDirectories(copy.getParent());
            Files.writeString(copy, source, StandardCharsets.UTF_8);
        }
        Map<String, Object> gradescope = grade(dir, "shouting");
        Path prairieLearn = FOLDER.getRoot().toPath().resolve("grade-shouting-pl");
        assertEquals(0, new CommandLine(new Grader()).execute("--project", PROJECT.toString(), "--classpath", LIBRARIES,
                "--submission", dir.toString(), "--out", prairieLearn.toString(), "--format", "prairielearn"));
        for (Path file : List.of(FOLDER.getRoot().toPath().resolve("grade-shouting/results.json"), prairieLearn.resolve("results.json"))) {
            long bytes = Files.size(file);
            assertTrue(file + ": " + bytes + " bytes", bytes <= OutputLimits.RESULTS_BYTES);
            // The failed renders' messages no longer point at a report on the grading machine.
            String json = Files.readString(file, StandardCharsets.UTF_8);
            assertTrue(file + " names a file on the grading machine", !json.contains("file:") && !json.contains(FOLDER.getRoot().toString()));
        }
        List<Map<String, Object>> failedSphere = ((List<Map<String, Object>>) gradescope.get("tests")).stream()
                .filter(t -> ((String) t.get("name")).startsWith("Task 2 ") && "failed".equals(t.get("status")))
                .collect(Collectors.toList());
        assertTrue("the sphere's tests fail", failedSphere.size() > 10);
        for (Map<String, Object> t : failedSphere) {
            String output = (String) t.get("output");
            assertTrue(t.get("name") + ": " + output.length() + " chars", output.length() < 2 * OutputLimits.MESSAGE_CHARS + 60_000);
        }
        assertTrue(failedSphere.stream().anyMatch(t -> ((String) t.get("output")).contains("… (cut)")));
        // Every other task keeps its points.
        double otherPoints = ((List<Map<String, Object>>) gradescope.get("tests")).stream()
                .filter(t -> !((String) t.get("name")).startsWith("Task 2 ")).mapToDouble(t -> (Double) t.get("score")).sum();
        double otherMax = ((List<Map<String, Object>>) gradescope.get("tests")).stream()
                .filter(t -> !((String) t.get("name")).startsWith("Task 2 ") && !((List<String>) t.get("tags")).contains("bonus"))
                .mapToDouble(t -> (Double) t.get("max_score")).sum();
        assertTrue(otherPoints + " of " + otherMax, otherPoints >= otherMax);
    }

    /**
     * A sphere that hits on every ray, whatever the segment (a real 2017 attempt's), answers every
     * question of a search with a hit, so each ray's answers are many: they still fit the wire, and its
     * renders fail by their pictures, not by the worker's end.
     */
    @Test(timeout = 600_000)
    @SuppressWarnings("unchecked")
    public void aSphereThatHitsOnEveryRayFailsItsRendersByThePicture() throws Exception {
        Path flat = FOLDER.getRoot().toPath().resolve("submission-hits-everywhere");
        Files.createDirectories(flat);
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            Files.copy(PROJECT.resolve(file), flat.resolve(Path.of(file).getFileName().toString()));
        }
        Files.copy(Path.of(DiagnosisCase.ATTEMPTS, "2017-ray1", "Sphere.java"), flat.resolve("Sphere.java"),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Path out = FOLDER.getRoot().toPath().resolve("grade-hits-everywhere");
        assertEquals(0, new CommandLine(new Grader()).execute("--project", PROJECT.toString(), "--classpath", LIBRARIES,
                "--submission", flat.toString(), "--out", out.toString(), "--task", "2"));
        Map<String, Object> results = new Gson().fromJson(Files.readString(out.resolve("results.json"), StandardCharsets.UTF_8), Map.class);
        List<Map<String, Object>> renders = ((List<Map<String, Object>>) results.get("tests")).stream()
                .filter(t -> ((String) t.get("name")).contains("SphereRenderTest.rendersLikeTheReference[")).collect(Collectors.toList());
        assertTrue(renders.stream().anyMatch(t -> ((String) t.get("name")).contains("[far-tiny-sphere]")));
        for (Map<String, Object> t : renders) {
            assertEquals(t.get("name").toString(), "failed", t.get("status"));
            assertTrue(t.get("name") + ": " + t.get("output"), ((String) t.get("output")).contains(" does not look like "));
        }
    }

    private static String insertAfter(String source, String anchor, String inserted) {
        int at = source.indexOf(anchor);
        assertTrue("anchor " + anchor, at >= 0);
        return source.substring(0, at + anchor.length()) + inserted + source.substring(at + anchor.length());
    }

    private static void put(ZipOutputStream z, String name, String text) throws Exception {
        z.putNextEntry(new ZipEntry(name));
        z.write(text.getBytes(StandardCharsets.UTF_8));
        z.closeEntry();
    }
}
