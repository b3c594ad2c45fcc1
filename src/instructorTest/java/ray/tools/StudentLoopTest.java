package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.StudentFiles;

/**
 * A student's edit–test loop, run as the student runs it: real Gradle (Debian's, on the PATH) in a
 * finished handout with one deliberate mistake at a time. What it checks is what the student reads:
 * the summary names the task whose code is wrong and no other, one exception is one entry, a render
 * that differs while every unit test passes is listed under "Renders", `-Ptask=N` runs one task, an
 * up-to-date run repeats the summary, and the summary is the last thing printed.
 */
public class StudentLoopTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".").toAbsolutePath().normalize();
    private static final Pattern CLOSING = Pattern.compile("^Tests: (\\d+) passed, (\\d+) failed, (\\d+) skipped$");
    private static final Pattern SECTION = Pattern.compile("^(Task \\d \\([^)]*\\)|Renders|Not part of a task): ", Pattern.MULTILINE);
    private static Path handout;

    @BeforeClass
    public static void buildFinishedHandout() throws Exception {
        assumeTrue("no gradle on the PATH", onPath("gradle"));
        handout = FOLDER.getRoot().toPath().resolve("ray1");
        Handout.build(PROJECT, handout);
        for (String file : StudentFiles.in(PROJECT).keySet()) {
            Files.copy(PROJECT.resolve(file), handout.resolve(file), StandardCopyOption.REPLACE_EXISTING);
        }
        // This test's own Gradle daemon leaves a minute after its last build, not three hours later
        // (`gradle --stop` would stop every daemon of the version, the one running this test too).
        Files.writeString(handout.resolve("gradle.properties"), "org.gradle.daemon.idletimeout=60000\n");
    }

    @Test
    public void aTriangleWithoutTheSumCheckIsListedUnderTask3Alone() throws Exception {
        String out = withVariant("src/main/java/ray/surface/Triangle.java", "triangle-no-sum-check", "test");
        // The bug also breaks camera and group scenes (they hold triangles): they go under Task 3.
        assertEquals(out, List.of("Task 3 (Triangle)"), sections(out));
        assertTrue(out, out.contains("CameraRenderTest > rendersLikeTheReference[antialiased]")
                || out.contains("GroupRenderTest > rendersLikeTheReference[group-transforms]") || out.contains("and 3 more"));
        assertTrue(out, out.contains("Work on the TODO(Task 3) comments in src/main/java/ray/surface/Triangle.java."));
        assertFailedAndSummaryLast(out);
    }

    @Test
    public void anOffByOneGroupIsOneExceptionUnderTask4() throws Exception {
        String loop = Files.readString(variant("group-index-loop", "ray/surface/Group.java"), StandardCharsets.UTF_8);
        String offByOne = loop.replace("i < surfaces.size()", "i <= surfaces.size()");
        assertNotEquals("the variant's loop changed; update this test", loop, offByOne);
        String out = withSource("src/main/java/ray/surface/Group.java", offByOne, "test");
        assertEquals(out, List.of("Task 4 (Group)"), sections(out));
        assertEquals(out, 1, count(out, "threw java.lang.IndexOutOfBoundsException"));
        assertTrue(out, Pattern.compile("\\(in \\d{2} tests: ").matcher(out).find());
        assertFailedAndSummaryLast(out);
    }

    @Test
    public void anExceptionFromTheSphereShowsUnderTask2Alone() throws Exception {
        String solution = Files.readString(PROJECT.resolve("src/main/java/ray/surface/Sphere.java"), StandardCharsets.UTF_8);
        String throwing = solution.replaceFirst("(public boolean intersect\\([^)]*\\) \\{)",
                "$1\n        if (ray != null) {\n            throw new IllegalStateException(\"deliberate\");\n        }");
        assertNotEquals(solution, throwing);
        String out = withSource("src/main/java/ray/surface/Sphere.java", throwing, "test");
        assertEquals(out, List.of("Task 2 (Sphere)"), sections(out));
        assertEquals(out, 1, count(out, "your code threw java.lang.IllegalStateException: deliberate at Sphere.java:"));
        assertFailedAndSummaryLast(out);
    }

    @Test
    public void aRenderThatDiffersWhileEveryUnitTestPassesIsListedOnceUnderRenders() throws Exception {
        Path reference = handout.resolve("scenes/reference/one-sphere.png");
        byte[] original = Files.readAllBytes(reference);
        try {
            BufferedImage image = ImageIO.read(reference.toFile());
            for (int x = 100; x < 130; x++) {
                for (int y = 100; y < 130; y++) {
                    image.setRGB(x, y, 0xff00ff);
                }
            }
            ImageIO.write(image, "png", reference.toFile());
            String out = gradle("test");
            assertEquals(out, List.of("Renders"), sections(out));
            assertEquals(out, 1, count(out, "SphereRenderTest > rendersLikeTheReference[one-sphere]"));
            assertTrue(out, out.contains("The scene uses Task 1 (Camera rays), Task 2 (Sphere) and Task 4 (Group)."));
            assertTrue(out, out.contains("render-diff/index.html#SphereRenderTest-one-sphere"));
            assertFailedAndSummaryLast(out);
        } finally {
            Files.write(reference, original);
        }
    }

    /**
     * A RepeatTexture one row off fails Task 5's unit tests, and the eclipse render, whose earth is
     * a RepeatTexture written inline in its shader, goes under Task 5 with them: never under
     * "Renders", which would say every task its scene uses passes.
     */
    @Test
    public void aTextureRenderGoesUnderItsFailingTaskNotUnderRenders() throws Exception {
        String out = withVariant("src/main/java/ray/shading/RepeatTexture.java", "texture-rows-flipped-after-rounding", "test", "-Ptask=5");
        assertEquals(out, List.of("Task 5 (Textures)"), sections(out));
        assertTrue(out, out.contains("TextureRenderTest > rendersLikeTheReference[eclipse]") || out.contains(" more"));
        assertFalse(out, out.contains("Renders:"));
        assertFailedAndSummaryLast(out);
    }

    @Test
    public void oneTaskRunsAloneAndAnUpToDateRunRepeatsItsSummary() throws Exception {
        String out = gradle("test", "-Ptask=2");
        Matcher closing = closing(out);
        assertEquals(out, "0", closing.group(2));
        int sphereTests = Integer.parseInt(closing.group(1));
        // SphereTest, SphereRandomTest, SphereTexCoordsTest and the five sphere scenes, nothing else.
        assertTrue(out, sphereTests >= 20 && sphereTests < 40);
        String again = gradle("test", "-Ptask=2");
        assertTrue(again, again.contains("Nothing changed since the last gradle test; its summary again:"));
        assertEquals(again, closing.group(), closing(again).group());
        String wrong = gradle("test", "-Ptask=9");
        assertTrue(wrong, wrong.contains("-Ptask=9: there is no such task in this assignment; give a number or id of 1 (camera-rays), 2 (sphere)"));
    }

    /**
     * On Java 24 and later Gradle 4.4's test worker cannot start, and `:test` runs the classes with
     * JUnit directly: what the student reads must be what the worker route prints. The failure is
     * Gradle's own for a failing test task (no script location, no other task's name), the summary
     * is last, a passing run prints no "SKIPPED", and an unchanged rerun is up to date and repeats
     * the summary. Gradle's "* Try:" lines (--stacktrace, --scan) follow every failed build on both
     * routes; they are Gradle's and no build setting removes them, so this compares them with the
     * worker route instead of forbidding them.
     */
    @Test
    public void theJava24RoutePrintsWhatTheWorkerRoutePrints() throws Exception {
        Path java24 = javaHomeOf24OrLater();
        assumeTrue("no JDK 24 or later in /usr/lib/jvm or RAY1_JAVA24_HOME", java24 != null);
        String triangle = "src/main/java/ray/surface/Triangle.java";
        String onWorker = withVariant(triangle, "triangle-no-sum-check", "test", "-Ptask=3");
        String route = withSource(triangle, Files.readString(variant("triangle-no-sum-check", "ray/surface/Triangle.java")),
                java24, "test", "-Ptask=3");
        assertTrue(route, route.contains("running the tests with JUnit directly"));
        assertFailedAndSummaryLast(route);
        for (String absent : List.of("legacy-test-worker.gradle", "* Where:", "WithJUnit", "SKIPPED")) {
            assertFalse(absent + " in:\n" + route, route.contains(absent));
        }
        assertTrue(route, route.contains("Execution failed for task ':test'.\n> There were failing tests."));
        assertEquals(route, gradleBlockHeadings(onWorker), gradleBlockHeadings(route));
        assertEquals(route, count(onWorker, "--scan"), count(route, "--scan"));
        assertEquals(route, closing(onWorker).group(), closing(route).group());
        assertEquals(route, sections(onWorker), sections(route));

        String passing = gradle(java24, "test", "-Ptask=3");
        assertFalse(passing, passing.contains("SKIPPED"));
        assertEquals(passing, "0", closing(passing).group(2));
        String again = gradle(java24, "test", "-Ptask=3");
        assertTrue(again, again.contains(":test UP-TO-DATE"));
        assertTrue(again, again.contains("Nothing changed since the last gradle test; its summary again:"));
        assertEquals(again, closing(passing).group(), closing(again).group());
    }

    /** Gradle's failure block as its headings ("* What went wrong:", "* Try:", ...), in order. */
    private static List<String> gradleBlockHeadings(String out) {
        return out.lines().filter(l -> l.startsWith("* ") || l.startsWith("FAILURE:") || l.startsWith("BUILD "))
                .map(l -> l.startsWith("BUILD ") ? l.replaceFirst(" in .*", "") : l).collect(Collectors.toList());
    }

    /** A JDK of Java 24 or later (RAY1_JAVA24_HOME, else the newest in /usr/lib/jvm), or null. */
    private static Path javaHomeOf24OrLater() throws IOException {
        String given = System.getenv("RAY1_JAVA24_HOME");
        if (given != null && !given.isBlank()) {
            return Path.of(given);
        }
        Path jvms = Path.of("/usr/lib/jvm");
        if (!Files.isDirectory(jvms)) {
            return null;
        }
        Pattern version = Pattern.compile("JAVA_VERSION=\"(\\d+)");
        try (var homes = Files.list(jvms)) {
            return homes.filter(h -> Files.isExecutable(h.resolve("bin/javac")) && Files.isRegularFile(h.resolve("release")))
                    .filter(h -> {
                        try {
                            Matcher m = version.matcher(Files.readString(h.resolve("release")));
                            return m.find() && Integer.parseInt(m.group(1)) >= 24;
                        } catch (IOException e) {
                            return false;
                        }
                    }).sorted().reduce((a, b) -> b).orElse(null);
        }
    }

    /** The sections the summary lists, in order ("Task 3 (Triangle)", "Renders", ...). */
    private static List<String> sections(String out) {
        List<String> found = new ArrayList<>();
        Matcher m = SECTION.matcher(out);
        while (m.find()) {
            found.add(m.group(1));
        }
        return found;
    }

    private static void assertFailedAndSummaryLast(String out) {
        Matcher closing = closing(out);
        assertNotEquals(out, "0", closing.group(2));
        List<String> lines = out.lines().filter(l -> !l.isBlank()).collect(Collectors.toList());
        assertTrue("Gradle's own lines follow the summary:\n" + out, CLOSING.matcher(lines.get(lines.size() - 1)).matches());
        assertFalse(out, out.contains("Not part of a task"));
    }

    private static Matcher closing(String out) {
        Matcher m = Pattern.compile("^Tests: (\\d+) passed, (\\d+) failed, (\\d+) skipped$", Pattern.MULTILINE).matcher(out);
        assertTrue("no closing line:\n" + out, m.find());
        return m;
    }

    private static int count(String text, String part) {
        int n = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
            n++;
        }
        return n;
    }

    private static Path variant(String name, String file) {
        return PROJECT.resolve("src/instructorTest/variants").resolve(name).resolve(file);
    }

    private static String withVariant(String file, String variant, String... args) throws Exception {
        return withSource(file, Files.readString(variant(variant, file.substring("src/main/java/".length())), StandardCharsets.UTF_8), args);
    }

    /** Runs gradle with {@code file} holding {@code source}, then puts the solution back. */
    private static String withSource(String file, String source, String... args) throws Exception {
        return withSource(file, source, null, args);
    }

    /** The same, with Gradle on the JDK at {@code javaHome} (null: the one this test runs on). */
    private static String withSource(String file, String source, Path javaHome, String... args) throws Exception {
        Path target = handout.resolve(file);
        try {
            Files.writeString(target, source, StandardCharsets.UTF_8);
            return gradle(javaHome, args);
        } finally {
            Files.copy(PROJECT.resolve(file), target, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** What `gradle ARGS --console=plain --offline` prints in the handout, stdout and stderr together. */
    private static String gradle(String... args) throws IOException, InterruptedException {
        return gradle(null, args);
    }

    /** The same, with Gradle (its daemon and so the tests) on the JDK at {@code javaHome} (null: this test's). */
    private static String gradle(Path javaHome, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of("gradle", "--console=plain", "--offline"));
        command.addAll(List.of(args));
        Path log = Files.createTempFile(FOLDER.getRoot().toPath(), "gradle", ".log");
        ProcessBuilder builder = new ProcessBuilder(command).directory(handout.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        if (javaHome != null) {
            builder.environment().put("JAVA_HOME", javaHome.toString());
        }
        Process process = builder.start();
        if (!process.waitFor(10, TimeUnit.MINUTES)) {
            process.destroyForcibly();
            throw new AssertionError("gradle " + String.join(" ", args) + " did not finish in 10 minutes");
        }
        return Files.readString(log, StandardCharsets.UTF_8);
    }

    private static boolean onPath(String program) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(dir, program))) {
                return true;
            }
        }
        return false;
    }
}
