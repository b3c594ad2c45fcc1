package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.util.List;
import org.junit.Test;

/**
 * What a run reports cannot add a test, change a test's points, or count a test twice: the grade
 * follows the instructor's list.
 */
public class ListedOutcomesTest {
    private static TestOutcome listed(String id, double points) {
        return new TestOutcome(id, id.split("#")[0], id.split("#")[1], 2, "Sphere", points, false, "visible", false, "", 0);
    }

    private static TestOutcome reported(String id, boolean passed, double points) {
        return new TestOutcome(id, id.split("#")[0], id.split("#")[1], 2, "Sphere", points, false, "visible", passed,
                passed ? "" : "expected a hit", 0.5);
    }

    private static double score(List<TestOutcome> outcomes) {
        return outcomes.stream().filter(TestOutcome::passed).mapToDouble(TestOutcome::points).sum();
    }

    @Test
    public void aForgedTestOfItsOwnCountsForNothing() {
        List<TestOutcome> judged = ListedOutcomes.judged(List.of(listed("SphereTest#a", 2)),
                List.of(reported("SphereTest#a", false, 2), reported("SphereTest#forged", true, 1000)));
        assertEquals(1, judged.size());
        assertEquals("SphereTest#a", judged.get(0).id());
        assertEquals(0, score(judged), 0);
    }

    @Test
    public void pointsAreTheListsWhateverTheReportSays() {
        List<TestOutcome> judged = ListedOutcomes.judged(List.of(listed("SphereTest#a", 2), listed("SphereTest#b", 3)),
                List.of(reported("SphereTest#b", true, 1000), reported("SphereTest#a", true, 0)));
        assertEquals(List.of("SphereTest#a", "SphereTest#b"), judged.stream().map(TestOutcome::id).collect(java.util.stream.Collectors.toList()));
        assertEquals(5, score(judged), 0);
        assertEquals(0.5, judged.get(0).seconds(), 0);
    }

    @Test
    public void aTestReportedTwiceOrNeverFailsSayingSo() {
        List<TestOutcome> judged = ListedOutcomes.judged(List.of(listed("SphereTest#a", 2), listed("SphereTest#b", 3),
                listed("SphereTest#c", 1)),
                List.of(reported("SphereTest#a", false, 2), reported("SphereTest#a", true, 2), reported("SphereTest#c", true, 1)));
        assertFalse(judged.get(0).passed());
        assertEquals("this test reported 2 results", judged.get(0).message());
        assertFalse(judged.get(1).passed());
        assertEquals("this test reported no result", judged.get(1).message());
        assertTrue(judged.get(2).passed());
        assertEquals(1, score(judged), 0);
    }
}
