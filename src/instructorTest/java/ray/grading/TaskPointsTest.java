package ray.grading;

import static org.junit.Assert.assertEquals;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.assignment.Assignment;

/** A task's points from the assignment, shared among its tests in proportion to their @Points. */
public class TaskPointsTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static TestOutcome test(String name, int task, double points, boolean bonus) {
        return GradescopeResultsTest.outcome(name, "m", task, points, bonus, true);
    }

    private static double sum(List<TestOutcome> tests, int task, boolean bonus) {
        return tests.stream().filter(t -> t.task() == task && t.bonus() == bonus).mapToDouble(TestOutcome::points).sum();
    }

    private final List<TestOutcome> listed = List.of(
            test("SphereTest", 2, 1, false), test("SphereTest", 2, 2, false), test("SphereRenderTest", 2, 2, false),
            test("SphereHardCasesBonusTest", 2, 1, true),
            test("TriangleTest", 3, 3, false),
            test("CylinderTest", 6, 1, true), test("CylinderRenderTest", 6, 3, true));

    @Test
    public void theTablesPointsForTodaysTasksAreTheirTestsPointsUnchanged() {
        Assignment intersections = Assignment.preset("intersections");
        assertEquals(39, intersections.points("sphere"), 0);
        assertEquals(14, intersections.points("cylinder"), 0);
    }

    @Test
    public void anAssignmentsPointsAreSharedByEachTestsShare() throws Exception {
        Path file = folder.getRoot().toPath().resolve("term.properties");
        Files.writeString(file, "preset = intersections\npoints.sphere = 10\npoints.triangle = 0\npoints.cylinder = 8\n",
                StandardCharsets.UTF_8);
        Assignment term = Assignment.resolve(folder.getRoot().toPath(), "term.properties", Map.of());
        List<TestOutcome> shared = TaskPoints.shared(listed, term);
        // The sphere's regular tests, weighted 1 : 2 : 2, share 10 points; its bonus test keeps its own.
        assertEquals(2, shared.get(0).points(), 1e-12);
        assertEquals(4, shared.get(1).points(), 1e-12);
        assertEquals(4, shared.get(2).points(), 1e-12);
        assertEquals(10, sum(shared, 2, false), 1e-12);
        assertEquals(1, sum(shared, 2, true), 0);
        // A task worth 0 keeps its tests' own points; an extra-credit task's bonus tests share its points.
        assertEquals(3, sum(shared, 3, false), 0);
        assertEquals(2, shared.get(5).points(), 1e-12);
        assertEquals(6, shared.get(6).points(), 1e-12);
        assertEquals(listed.stream().map(TestOutcome::id).collect(java.util.stream.Collectors.toList()),
                shared.stream().map(TestOutcome::id).collect(java.util.stream.Collectors.toList()));
    }

    @Test
    public void aBadNumberOfPointsIsOneLine() {
        try {
            Assignment.resolve(Path.of("."), "intersections", Map.of("points.sphere", "many"));
            org.junit.Assert.fail();
        } catch (ray.assignment.AssignmentException | java.io.IOException e) {
            assertEquals("intersections with points.sphere given: points.sphere is \"many\"; expected a number of points, 0 or more",
                    e.getMessage());
        }
    }
}
