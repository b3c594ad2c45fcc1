package ray.grading;

/**
 * One graded test's result.
 *
 * @param id          "ClassName#method" as JUnit names it (parameterized tests add "[name]")
 * @param task        the task number the points count toward
 * @param points      what the test is worth
 * @param bonus       extra credit: {@code points} are earned when it passes, nothing is lost when it fails
 * @param visibility  Gradescope's visibility value
 * @param message     why it failed (empty when it passed)
 */
public record TestOutcome(String id, String className, String method, int task, String taskTitle, double points,
        boolean bonus, String visibility, boolean passed, String message, double seconds) {

    TestOutcome withMessage(String message) {
        return new TestOutcome(id, className, method, task, taskTitle, points, bonus, visibility, passed, message, seconds);
    }

    /** This listed test with the result (passed, message, seconds) of {@code ran}, a report of the same test. */
    TestOutcome withResultOf(TestOutcome ran) {
        return new TestOutcome(id, className, method, task, taskTitle, points, bonus, visibility, ran.passed, ran.message, ran.seconds);
    }

    TestOutcome withPoints(double points) {
        return new TestOutcome(id, className, method, task, taskTitle, points, bonus, visibility, passed, message, seconds);
    }

    TestOutcome failedWith(String why) {
        return new TestOutcome(id, className, method, task, taskTitle, points, bonus, visibility, false, why, seconds);
    }

    /** Whether a test class is one of the whole-scene render tests (package ray.endtoend), not a unit test. */
    static boolean isRenderTestClass(String className) {
        return className.startsWith("ray.endtoend.");
    }

    /** Whether this is a whole-scene render test's outcome, not a unit test's. */
    boolean isRenderTest() {
        return isRenderTestClass(className);
    }

    /** The points this outcome earns: all of them when it passed, none when it failed. */
    public double earned() {
        return passed ? points : 0;
    }

    /**
     * The points it adds to the maximum score: its points, or none for a bonus test (a bonus test's
     * own entry still shows its points as its maximum: earned of offered).
     */
    public double possible() {
        return bonus ? 0 : points;
    }
}
