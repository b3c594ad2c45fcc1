package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The test JVM survives student code at its worst: a System.exit, an infinite loop that ignores
 * interrupts, unbounded allocation, an assertion on NaN. Each costs its own test only, and every
 * test after it still runs. Runs a small project compiled here, with graded, bonus and ungraded
 * tests: the bonus flag of @Points reaches each outcome.
 */
public class TestProcessTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    // Graded test classes count toward the task whose test patterns in the table of tasks match their
    // names: the demo classes are named as the sphere's and the triangle's tests are.
    private static final String DEMO = String.join("\n",
            "package ray.surface;",
            "import static org.junit.Assert.assertEquals;",
            "import org.junit.FixMethodOrder;",
            "import org.junit.Test;",
            "import org.junit.runners.MethodSorters;",
            "import ray.testing.Points;",
            "import ray.testing.Visibility;",
            "@Points(1)",
            "@FixMethodOrder(MethodSorters.NAME_ASCENDING)",
            "public class SphereDemoTest {",
            "    @Test public void a_passes() { }",
            "    @Test public void b_failsAnAssertion() { assertEquals(1, 2); }",
            "    @Test public void c_callsSystemExit() { System.exit(3); }",
            "    @Test public void d_loopsForeverIgnoringInterrupts() { while (true) { Thread.interrupted(); } }",
            "    @Test public void e_allocatesWithoutBound() {",
            "        java.util.List<long[]> hoard = new java.util.ArrayList<>();",
            "        while (true) { hoard.add(new long[1 << 20]); }",
            "    }",
            "    @Test public void f_comparesNaN() { assertEquals(0.5, Double.NaN, 1e-9); }",
            "    @Points(value = 2, bonus = true)",
            "    @Test public void h_bonusPasses() { }",
            "    @Points(value = 0.5, bonus = true)",
            "    @Test public void i_bonusFails() { assertEquals(\"bonus\", \"nope\"); }",
            "}",
            "");
    /** A hidden test of another task (the group's, by its name). */
    private static final String GROUP_DEMO = String.join("\n",
            "package ray.surface;",
            "import ray.testing.Points;",
            "import ray.testing.Visibility;",
            "public class GroupDemoTest {",
            "    @Points(value = 3, visibility = Visibility.HIDDEN)",
            "    @org.junit.Test public void g_hiddenAndWorthThree() { }",
            "}",
            "");
    /** Student code run from a static initializer that exits: before any test starts, unless the runner defers it. */
    private static final String EXITING_INITIALIZER = String.join("\n",
            "package ray.surface;",
            "@ray.testing.Points(1)",
            "public class TriangleExitingInitializerTest {",
            "    static final int VALUE = exit();",
            "    static int exit() { System.exit(5); return 0; }",
            "    @org.junit.Test public void first() { }",
            "    @org.junit.Test public void second() { }",
            "}",
            "");
    private static final String UNGRADED = "package demo;\npublic class UngradedTest {\n"
            + "    @org.junit.Test public void notCounted() { }\n}\n";

    private static Path project;

    @BeforeClass
    public static void compileDemoProject() throws Exception {
        project = FOLDER.getRoot().toPath().resolve("demo-project");
        Path tests = project.resolve("src/test/java/demo");
        Path graded = project.resolve("src/test/java/ray/surface");
        Files.createDirectories(tests);
        Files.createDirectories(graded);
        Files.writeString(graded.resolve("SphereDemoTest.java"), DEMO, StandardCharsets.UTF_8);
        Files.writeString(graded.resolve("GroupDemoTest.java"), GROUP_DEMO, StandardCharsets.UTF_8);
        Files.writeString(tests.resolve("UngradedTest.java"), UNGRADED, StandardCharsets.UTF_8);
        Files.writeString(graded.resolve("TriangleExitingInitializerTest.java"), EXITING_INITIALIZER, StandardCharsets.UTF_8);
        CompileResult compiled = ProjectCompiler.compile(project, project.resolve("classes"), System.getProperty("java.class.path"));
        assertTrue(compiled.messages(), compiled.ok());
    }

    private static TestProcess process(String work) {
        return new TestProcess(project, project.resolve("classes"), System.getProperty("java.class.path"),
                project.resolve(work)).withHardLimitSeconds(4);
    }

    @Test(timeout = 120_000)
    public void everyFailureCostsOnlyItsOwnTestAndLaterTestsStillRun() throws Exception {
        List<TestOutcome> all = process("run-all").run(null);
        List<TestOutcome> outcomes = all.stream().filter(t -> t.className().matches("ray\\.surface\\.(Sphere|Group)DemoTest"))
                .sorted(java.util.Comparator.comparing(TestOutcome::method)).collect(Collectors.toList());
        Map<String, TestOutcome> byMethod = outcomes.stream().collect(Collectors.toMap(TestOutcome::method, Function.identity()));
        assertEquals(List.of("a_passes", "b_failsAnAssertion", "c_callsSystemExit", "d_loopsForeverIgnoringInterrupts",
                "e_allocatesWithoutBound", "f_comparesNaN", "g_hiddenAndWorthThree", "h_bonusPasses", "i_bonusFails"),
                outcomes.stream().map(TestOutcome::method).collect(Collectors.toList()));
        assertTrue(byMethod.get("a_passes").passed());
        assertFalse(byMethod.get("b_failsAnAssertion").passed());
        assertTrue(byMethod.get("b_failsAnAssertion").message(), byMethod.get("b_failsAnAssertion").message().startsWith("expected:<1> but was:<2>"));
        assertEquals("the code under test called System.exit, which ended the test JVM", byMethod.get("c_callsSystemExit").message());
        assertTrue(byMethod.get("d_loopsForeverIgnoringInterrupts").message(),
                byMethod.get("d_loopsForeverIgnoringInterrupts").message().startsWith("stopped after 4 s"));
        assertTrue(byMethod.get("e_allocatesWithoutBound").message(),
                byMethod.get("e_allocatesWithoutBound").message().contains("ran out of memory (java.lang.OutOfMemoryError"));
        assertFalse(byMethod.get("f_comparesNaN").passed());
        TestOutcome hidden = byMethod.get("g_hiddenAndWorthThree");
        assertTrue(hidden.passed());
        assertEquals(3, hidden.points(), 0);
        assertEquals(4, hidden.task());
        assertEquals("Group", hidden.taskTitle());
        assertEquals("hidden", hidden.visibility());
        assertEquals(1, byMethod.get("a_passes").points(), 0);
        assertEquals(2, byMethod.get("a_passes").task());
        assertEquals("visible", byMethod.get("a_passes").visibility());
        assertFalse(byMethod.get("a_passes").bonus());
        assertFalse(hidden.bonus());
        TestOutcome bonusPassed = byMethod.get("h_bonusPasses");
        assertTrue(bonusPassed.bonus());
        assertTrue(bonusPassed.passed());
        assertEquals(2, bonusPassed.points(), 0);
        assertEquals(2, bonusPassed.task());
        TestOutcome bonusFailed = byMethod.get("i_bonusFails");
        assertTrue(bonusFailed.bonus());
        assertFalse(bonusFailed.passed());
        assertEquals(0.5, bonusFailed.points(), 0);
        // Regular: a–f at 1 each (only a passed) and g at 3 (passed); bonus: h passed (2), i failed (0.5).
        Map<String, Object> results = GradescopeResults.of(outcomes, "", 1);
        assertEquals(6 + 3 + 0, GradescopeResults.maxScore(results), 0);
        assertEquals(1 + 3 + 2, (Double) results.get("score"), 0);
        // The class whose initializer exits costs each of its tests, and nothing else.
        List<TestOutcome> exiting = all.stream().filter(t -> t.className().equals("ray.surface.TriangleExitingInitializerTest"))
                .collect(Collectors.toList());
        assertEquals(2, exiting.size());
        for (TestOutcome t : exiting) {
            assertEquals("the code under test called System.exit, which ended the test JVM", t.message());
        }
    }

    @Test(timeout = 60_000)
    public void aTaskFilterRunsOnlyThatTasksTests() throws Exception {
        List<TestOutcome> outcomes = process("run-task-4").run(4);
        assertEquals(1, outcomes.size());
        assertEquals("g_hiddenAndWorthThree", outcomes.get(0).method());
    }

    @Test(timeout = 60_000)
    public void listingNamesEveryGradedTestWithoutRunningIt() throws Exception {
        List<TestOutcome> listed = process("list").list(null);
        assertEquals(11, listed.size());
        assertTrue(listed.stream().noneMatch(TestOutcome::passed));
        // DemoTest 1·6 + 3 + bonus 2 + 0.5, ExitingInitializerTest 1·2.
        assertEquals(13.5, listed.stream().mapToDouble(TestOutcome::points).sum(), 0);
        assertEquals(2, listed.stream().filter(TestOutcome::bonus).count());
    }
}
