package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.grading.VariantFolders.Variant;

/**
 * The diagnosis evaluation, run for real: every known-wrong variant graded by the grader is named,
 * in each of its failed render tests, and by nothing else; no correct variant gets a name; and the
 * held-out real attempt gets no name of a mistake it does not make, while its failures explain
 * its group's segment, its group's last-child answer and its camera's floats.
 */
public class DiagnosisEvaluationTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final Path PROJECT = Path.of(".").toAbsolutePath().normalize();
    private static final String CLASSPATH = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
            .collect(Collectors.joining(File.pathSeparator));

    @Test(timeout = 1_800_000)
    public void everyMistakeIsNamedRightAndNothingElseIsNamed() throws Exception {
        List<Variant> variants = VariantFolders.in(PROJECT, StudentFiles.in(PROJECT));
        Set<String> descriptions = new HashSet<>();
        for (Variant v : variants) {
            assertTrue("two known mistakes are described alike, so their names cannot be told apart: " + v.knownWrong,
                    v.knownWrong == null || descriptions.add(v.knownWrong));
        }
        DiagnosisEvaluation evaluation = new DiagnosisEvaluation();
        evaluation.project = PROJECT;
        evaluation.classpath = CLASSPATH;
        evaluation.out = folder.getRoot().toPath();
        evaluation.jobs = 2;
        List<DiagnosisRow> rows = evaluation.evaluate();
        String table = DiagnosisRow.table(rows);

        assertEquals(table, variants.size() + 1, rows.size());
        for (DiagnosisRow row : rows) {
            assertTrue(row.summary() + "\n" + table, row.wrong().isEmpty());
            switch (row.of().kind) {
                case WRONG:
                    assertEquals(table, Set.of(row.of().name), row.right());
                    assertEquals(row.of().name + ": each failed render names the mistake\n" + table, row.failedRenders(), row.rendersNamed());
                    break;
                case CORRECT:
                    assertTrue(table, row.right().isEmpty() && !row.flippedPicture());
                    break;
                default:
                    assertAttemptIsExplained(row);
            }
        }
    }

    /** The attempt's failures name what its numbers show: its group's segment and answer, and its camera's floats. */
    private static void assertAttemptIsExplained(DiagnosisRow attempt) {
        String all = attempt.feedback().failed().stream().map(GradedFeedback.Failed::output).collect(Collectors.joining("\n"));
        for (String expected : List.of("a group searches the caller's segment",
                "does yours return whether the last child it tried was?", "about float precision")) {
            assertTrue("the attempt's feedback must say \"" + expected + "\"", all.contains(expected));
        }
        Map<String, Long> byTask = attempt.feedback().failed().stream()
                .collect(Collectors.groupingBy(f -> f.name().replaceFirst(" \\(.*", ""), Collectors.counting()));
        assertTrue("the attempt fails tests of every task it attempted: " + byTask, byTask.keySet().containsAll(
                List.of("Task 1", "Task 2", "Task 3", "Task 4", "Task 5")));
    }
}
