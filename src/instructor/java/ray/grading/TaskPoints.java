package ray.grading;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import ray.assignment.Assignment;
import ray.assignment.Task;

/**
 * A task's points, shared among its tests: the assignment says what each task is worth
 * ({@link Assignment#points}), and each test's {@code @Points} says its share. A required task's
 * regular tests together are worth its points (its bonus tests, the hard cases, keep their own);
 * an extra-credit task's tests are all bonus tests, and together worth its points. A task worth 0
 * keeps its tests' own points.
 */
final class TaskPoints {
    private TaskPoints() {
    }

    /** The listed tests with their points shared so (the list's order kept). */
    static List<TestOutcome> shared(List<TestOutcome> listed, Assignment assignment) {
        Map<Integer, Double> weights = new HashMap<>();
        for (TestOutcome t : listed) {
            if (counted(t, assignment)) {
                weights.merge(t.task(), t.points(), Double::sum);
            }
        }
        List<TestOutcome> shared = new ArrayList<>(listed.size());
        for (TestOutcome t : listed) {
            double worth = assignment.task(t.task()).map(task -> assignment.points(task.id())).orElse(0.0);
            double total = weights.getOrDefault(t.task(), 0.0);
            shared.add(counted(t, assignment) && worth > 0 && total > 0 ? t.withPoints(worth * t.points() / total) : t);
        }
        return shared;
    }

    /** Whether the test shares its task's points: a regular test, or any test of an extra-credit task. */
    private static boolean counted(TestOutcome t, Assignment assignment) {
        return assignment.task(t.task()).map(Task::id).map(id -> assignment.isExtraCredit(id) || !t.bonus()).orElse(false);
    }
}
