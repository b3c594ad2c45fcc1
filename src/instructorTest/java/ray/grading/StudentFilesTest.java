package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** Which student files a submission may leave out: those of a task whose tests are all bonus tests. */
public class StudentFilesTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static TestOutcome test(int task, boolean bonus) {
        return new TestOutcome("T#m" + task + bonus, "T", "m", task, "Task " + task, 1, bonus, "visible", false, "", 0);
    }

    @Test
    public void onlyATaskOfBonusTestsAloneIsOptional() {
        Map<String, Integer> files = Map.of("src/main/java/A.java", 1, "src/main/java/B.java", 2, "src/main/java/C.java", 3,
                "src/main/java/D.java", 4, "src/main/java/E.java", 4);
        // Task 1: regular tests only; task 2: regular and bonus; task 3: no graded tests; task 4: bonus tests only.
        List<TestOutcome> tests = List.of(test(1, false), test(2, false), test(2, true), test(4, true), test(4, true));
        assertEquals(Set.of("src/main/java/D.java", "src/main/java/E.java"), StudentFiles.optional(files, tests));
    }

    @Test(timeout = 300_000)
    public void theCylinderIsThisProjectsOnlyOptionalFile() throws Exception {
        // This project's graded tests, listed as the grader lists them, from the classes gradle test already compiled.
        String classpath = System.getProperty("java.class.path");
        Path work = folder.getRoot().toPath();
        List<TestOutcome> tests = new TestProcess(Path.of("."), work.resolve("no-classes"), classpath, work.resolve("list")).list(null);
        assertTrue("the project has graded tests: " + tests.size(), tests.size() > 50);
        assertEquals(Set.of("src/main/java/ray/surface/Cylinder.java"), StudentFiles.optional(StudentFiles.in(Path.of(".")), tests));
    }
}
