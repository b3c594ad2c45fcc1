package ray.grading;

/**
 * One graded test's result.
 *
 * @param id          "ClassName#method" as JUnit names it (parameterized tests add "[name]")
 * @param task        the task number the points count toward
 * @param visibility  Gradescope's visibility value
 * @param message     why it failed (empty when it passed)
 */
public record TestOutcome(String id, String className, String method, int task, String taskTitle, double points,
        String visibility, boolean passed, String message, double seconds) {

    TestOutcome failedWith(String why) {
        return new TestOutcome(id, className, method, task, taskTitle, points, visibility, false, why, seconds);
    }
}
