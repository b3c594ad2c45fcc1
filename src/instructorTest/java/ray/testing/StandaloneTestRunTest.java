package ray.testing;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The JUnit launch that stands in for Gradle 4.4's test worker on Java 24 and later
 * ({@code gradle/legacy-test-worker.gradle}): run in its own JVM on small test classes compiled
 * here, it must count as Gradle counts (a failed @BeforeClass is one failed test, an ignored test and
 * a failed assumption are skipped), keep each failure's class, name, exception class and message,
 * skip classes that hold no tests, keep what tests print off the console, and select tests as
 * {@code gradle test --tests} does.
 */
public class StandaloneTestRunTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();
    private static Path classes;

    private static final Map<String, String> SAMPLES = Map.of(
            "sample/MixedTest.java", """
                    package sample;
                    import org.junit.*;
                    public class MixedTest {
                        @Test public void passes() {}
                        @Test public void prints() { System.out.println("printed by a test"); }
                        @Test public void fails() { Assert.fail("[Task 2 (Sphere)] expected a hit"); }
                        @Ignore @Test public void ignored() {}
                        @Test public void assumes() { Assume.assumeTrue(false); }
                    }
                    """,
            "sample/BrokenSetUpTest.java", """
                    package sample;
                    import org.junit.*;
                    public class BrokenSetUpTest {
                        @BeforeClass public static void setUp() { throw new IllegalStateException("no scene"); }
                        @Test public void never() {}
                    }
                    """,
            "sample/AbstractBaseTest.java", """
                    package sample;
                    public abstract class AbstractBaseTest { @org.junit.Test public void inherited() {} }
                    """,
            "sample/Helper.java", "package sample;\npublic class Helper { }\n");

    @BeforeClass
    public static void compileSamples() throws IOException {
        Path sources = FOLDER.newFolder("sources").toPath();
        classes = FOLDER.newFolder("classes").toPath();
        List<String> arguments = new ArrayList<>(List.of("-d", classes.toString(), "-cp", System.getProperty("java.class.path")));
        for (Map.Entry<String, String> sample : SAMPLES.entrySet()) {
            Path file = sources.resolve(sample.getKey());
            Files.createDirectories(file.getParent());
            Files.writeString(file, sample.getValue(), StandardCharsets.UTF_8);
            arguments.add(file.toString());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertEquals("the samples compile", 0, javac.run(null, null, null, arguments.toArray(new String[0])));
    }

    @Test
    public void countsAndReportsAsGradleDoes() throws Exception {
        Run run = run();
        assertEquals(run.console, 2, run.results.get("passed").getAsInt());
        assertEquals(2, run.results.get("failed").getAsInt());
        assertEquals(2, run.results.get("skipped").getAsInt());
        JsonObject failed = failure(run, "sample.MixedTest", "fails");
        assertEquals("java.lang.AssertionError", failed.get("exceptionClass").getAsString());
        assertEquals("[Task 2 (Sphere)] expected a hit", failed.get("message").getAsString());
        JsonObject setUp = failure(run, "sample.BrokenSetUpTest", "classMethod");
        assertEquals("java.lang.IllegalStateException", setUp.get("exceptionClass").getAsString());
        assertEquals("no scene", setUp.get("message").getAsString());
        assertTrue(run.output, run.output.contains("printed by a test"));
        assertFalse("what tests print stays off the console: " + run.console, run.console.contains("printed by a test"));
    }

    @Test
    public void selectsTestsAsGradleTestTestsDoes() throws Exception {
        Run one = run("--filter", "MixedTest.passes");
        assertEquals(1, one.results.get("passed").getAsInt());
        assertEquals(0, one.results.get("failed").getAsInt() + one.results.get("skipped").getAsInt());
        Run wildcard = run("--filter", "sample.*SetUp*");
        assertEquals(0, wildcard.results.get("passed").getAsInt());
        assertEquals(1, wildcard.results.get("failed").getAsInt());
        Run none = run("--filter", "*NoSuchTest");
        assertEquals(0, none.results.get("passed").getAsInt() + none.results.get("failed").getAsInt()
                + none.results.get("skipped").getAsInt());
    }

    private static JsonObject failure(Run run, String className, String name) {
        for (var element : run.results.getAsJsonArray("failures")) {
            JsonObject f = element.getAsJsonObject();
            if (f.get("className").getAsString().equals(className) && f.get("name").getAsString().equals(name)) {
                return f;
            }
        }
        throw new AssertionError("no failure " + className + " > " + name + " in " + run.results);
    }

    /** What one run in a child JVM left: its results, the tests' captured output and its console. */
    private record Run(JsonObject results, String output, String console) {
    }

    private static Run run(String... filter) throws IOException, InterruptedException {
        Path results = FOLDER.getRoot().toPath().resolve("results-" + System.nanoTime() + ".json");
        Path output = FOLDER.getRoot().toPath().resolve("output-" + System.nanoTime() + ".txt");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classes + File.pathSeparator + System.getProperty("java.class.path"),
                StandaloneTestRun.class.getName(), "--results", results.toString(), "--output", output.toString()));
        command.addAll(List.of(filter));
        command.addAll(List.of("sample.MixedTest", "sample.BrokenSetUpTest", "sample.AbstractBaseTest", "sample.Helper"));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String console = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(console, 0, process.waitFor());
        return new Run(JsonParser.parseString(Files.readString(results)).getAsJsonObject(), Files.readString(output), console);
    }
}
