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
 * When grading, a task's first test whose code never finishes ends that task's run: its later tests
 * fail at once, naming it, so a loop costs one time limit instead of one per test. A bonus test that
 * never finishes skips only the later bonus tests; the other tasks and, in a student's own run,
 * every test still run. Runs small projects compiled here with the real StudentTaskRule.
 */
public class UnfinishedTaskSkipTest {
    @ClassRule
    public static final TemporaryFolder FOLDER = new TemporaryFolder();

    /** A graded test class in {@code pkg}: its name and package make it one task's, by the table of tasks' test patterns. */
    private static String demo(String pkg, String className, int ruleSeconds, String... methods) {
        return String.join("\n",
                "package " + pkg + ";",
                "import org.junit.FixMethodOrder;",
                "import org.junit.Rule;",
                "import org.junit.Test;",
                "import org.junit.runners.MethodSorters;",
                "import ray.testing.Points;",
                "import ray.testing.StudentTaskRule;",
                "@Points(1)",
                "@FixMethodOrder(MethodSorters.NAME_ASCENDING)",
                "public class " + className + " {",
                "    @Rule public final StudentTaskRule rule = StudentTaskRule.of(getClass()).withTimeoutSeconds("
                        + ruleSeconds + ");",
                String.join("\n", methods),
                "}",
                "");
    }

    private static final String LOOP = "{ while (true) { Thread.onSpinWait(); } }";
    private static final String BONUS = "@Points(value = 1, bonus = true) ";
    private static Path project;

    @BeforeClass
    public static void compileDemoProject() throws Exception {
        project = FOLDER.getRoot().toPath().resolve("unfinished-project");
        Path sources = project.resolve("src/test/java/ray");
        for (String pkg : List.of("camera", "surface", "shading")) {
            Files.createDirectories(sources.resolve(pkg));
        }
        Files.writeString(sources.resolve("camera/CameraLoopTest.java"), demo("ray.camera", "CameraLoopTest", 1,
                "    @Test public void a_passes() { }",
                "    @Test public void b_loops() " + LOOP,
                "    @Test public void c_wouldPass() { }",
                "    @Points(value = 1, bonus = true) @Test public void d_bonusWouldPass() { }"),
                StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("surface/SphereFineTest.java"), demo("ray.surface", "SphereFineTest", 1,
                "    @Test public void passes() { }"), StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("surface/TriangleBonusLoopTest.java"), demo("ray.surface", "TriangleBonusLoopTest", 1,
                "    " + BONUS + "@Test public void a_bonusLoops() " + LOOP,
                "    " + BONUS + "@Test public void b_bonusWouldPass() { }",
                "    @Test public void c_regularPasses() { }"), StandardCharsets.UTF_8);
        Files.writeString(sources.resolve("shading/RepeatTextureHiddenLoopTest.java"), demo("ray.shading", "RepeatTextureHiddenLoopTest", 1,
                "    @Points(value = 1, visibility = ray.testing.Visibility.HIDDEN)"
                        + " @Test public void a_secretCaseLoops() " + LOOP,
                "    @Test public void b_wouldPass() { }"), StandardCharsets.UTF_8);
        // A loop that the rule's limit (60 s) does not reach before the grader's backstop (3 s) stops the JVM.
        Files.writeString(sources.resolve("surface/GroupStoppedTest.java"), demo("ray.surface", "GroupStoppedTest", 60,
                "    @Test public void a_loopsUntilStopped() " + LOOP,
                "    @Test public void b_wouldPass() { }"), StandardCharsets.UTF_8);
        CompileResult compiled = ProjectCompiler.compile(project, project.resolve("classes"), System.getProperty("java.class.path"));
        assertTrue(compiled.messages(), compiled.ok());
    }

    private static Map<String, TestOutcome> run(String work) throws Exception {
        List<TestOutcome> outcomes = new TestProcess(project, project.resolve("classes"), System.getProperty("java.class.path"),
                project.resolve(work)).withHardLimitSeconds(3).run(null);
        return outcomes.stream().collect(Collectors.toMap(t -> t.className().substring(t.className().lastIndexOf('.') + 1) + "." + t.method(), Function.identity()));
    }

    @Test(timeout = 300_000)
    public void aTasksLaterTestsFailAtOnceNamingTheTestThatDidNotFinish() throws Exception {
        long start = System.nanoTime();
        Map<String, TestOutcome> outcomes = run("run");
        double seconds = (System.nanoTime() - start) / 1e9;
        assertTrue(outcomes.get("CameraLoopTest.a_passes").passed());
        assertTrue(outcomes.get("CameraLoopTest.b_loops").message(),
                outcomes.get("CameraLoopTest.b_loops").message().contains("took longer than 1 s: is there a loop that never ends?"));
        for (String later : List.of("CameraLoopTest.c_wouldPass", "CameraLoopTest.d_bonusWouldPass")) {
            TestOutcome t = outcomes.get(later);
            assertFalse(later, t.passed());
            assertTrue(t.message(), t.message().startsWith("[Task 1 (Camera rays)")
                    && t.message().contains("] skipped: your code did not finish in test CameraLoopTest.b_loops,"
                            + " so this task's later tests were not run; make that test finish first"));
            // At once: below the 1 s its own limit would take (it takes milliseconds; the rest is room for a loaded machine).
            assertTrue(later + " failed at once: " + t.seconds() + " s", t.seconds() < 1);
        }
        assertTrue("another task still runs", outcomes.get("SphereFineTest.passes").passed());
        // A hidden test is not named, not even by its method.
        String afterHidden = outcomes.get("RepeatTextureHiddenLoopTest.b_wouldPass").message();
        assertTrue(afterHidden, afterHidden.contains("skipped: your code did not finish in a hidden test,")
                && !afterHidden.contains("secretCase"));
        // A bonus loop skips the later bonus tests of its task, not its regular ones.
        assertTrue(outcomes.get("TriangleBonusLoopTest.b_bonusWouldPass").message(),
                outcomes.get("TriangleBonusLoopTest.b_bonusWouldPass").message()
                        .contains("skipped: your code did not finish in test TriangleBonusLoopTest.a_bonusLoops"));
        assertTrue(outcomes.get("TriangleBonusLoopTest.c_regularPasses").passed());
        // The JVM the backstop stopped tells the next one which test did not finish.
        assertTrue(outcomes.get("GroupStoppedTest.a_loopsUntilStopped").message().startsWith("stopped after 3 s"));
        assertTrue(outcomes.get("GroupStoppedTest.b_wouldPass").message(), outcomes.get("GroupStoppedTest.b_wouldPass").message()
                .contains("skipped: your code did not finish in test GroupStoppedTest.a_loopsUntilStopped"));
        // Three limits of 1 s, one backstop of 3 s and two JVM starts, not a limit per test: the skips
        // above say so; this bound only stops a hang, with room for a loaded machine's JVM starts.
        assertTrue(seconds + " s", seconds < 120);
    }

    @Test
    public void unfinishedTestsArePassedOnFirstPerTaskAndKind() {
        List<TestOutcome> earlier = List.of(
                outcome("ray.surface.SphereTest", "a", 2, false, true, ""),
                outcome("ray.surface.SphereTest", "b", 2, false, false, "[Task 2 (Sphere)] took longer than 10 s: is there a loop"),
                outcome("ray.surface.SphereTest", "c", 2, false, false, "stopped after 120 s: the test never finished"),
                outcome("ray.surface.TriangleHardCasesBonusTest", "d", 3, true, false, "stopped after 120 s: the test never finished"),
                outcome("ray.surface.GroupTest", "e", 4, false, false, "expected:<1> but was:<2>"),
                hidden(outcome("ray.hidden.GroupHiddenTest", "f", 4, false, false, "stopped after 120 s: the test never finished")));
        assertEquals("2=test SphereTest.b;3+bonus=test TriangleHardCasesBonusTest.d;4=a hidden test", TestProcess.unfinished(earlier));
        assertEquals("", TestProcess.unfinished(List.of()));
    }

    private static TestOutcome hidden(TestOutcome t) {
        return new TestOutcome(t.id(), t.className(), t.method(), t.task(), t.taskTitle(), t.points(), t.bonus(), "hidden", t.passed(),
                t.message(), t.seconds());
    }

    private static TestOutcome outcome(String className, String method, int task, boolean bonus, boolean passed, String message) {
        return new TestOutcome(className + "#" + method, className, method, task, "Task", 1, bonus, "visible", passed, message, 0);
    }
}
