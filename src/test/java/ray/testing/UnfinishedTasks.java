package ray.testing;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * When grading, the first test of a task whose code never finishes ends that task's run: its later
 * tests fail at once, naming that test, instead of each waiting out its own time limit while one
 * more abandoned thread spins (the grader's whole run has a deadline; a loop in Sphere.intersect
 * used to cost every Sphere test its 10 s, and the threads left spinning slowed the rest). A timeout
 * in a bonus test skips only that task's later bonus tests.
 *
 * <p>Only the grader turns this on (system property {@value #SKIP_PROPERTY}); in a student's own
 * {@code gradle test} every test runs. A grader that had to stop a test JVM passes the tests that
 * never finished to the next one in {@value #EARLIER_PROPERTY}: entries {@code TASK=TEST} or
 * {@code TASK+bonus=TEST}, separated by {@code ;}.
 */
public final class UnfinishedTasks {
    static final String SKIP_PROPERTY = "ray1.grading.skipAfterTimeout";
    static final String EARLIER_PROPERTY = "ray1.grading.unfinished";
    private static final Map<String, String> FIRST_UNFINISHED = new ConcurrentHashMap<>();
    /** The test ("Class#method") whose rule was entered last: the grader's runner tells a test stuck before it. */
    private static volatile String entered;

    static {
        String earlier = System.getProperty(EARLIER_PROPERTY, "");
        for (String entry : earlier.split(";")) {
            int equals = entry.indexOf('=');
            if (equals > 0) {
                FIRST_UNFINISHED.putIfAbsent(entry.substring(0, equals), entry.substring(equals + 1));
            }
        }
    }

    private UnfinishedTasks() {
    }

    private static String key(StudentTask task, boolean bonus) {
        return task.number + (bonus ? "+bonus" : "");
    }

    private static boolean skipping() {
        return Boolean.getBoolean(SKIP_PROPERTY);
    }

    /** The test of this task that did not finish and makes this one be skipped, or null to run it. */
    static String skipBecauseOf(StudentTask task, boolean bonus) {
        if (!skipping()) {
            return null;
        }
        String regular = FIRST_UNFINISHED.get(key(task, false));
        return regular != null || !bonus ? regular : FIRST_UNFINISHED.get(key(task, true));
    }

    /** The whole message a skipped test of this task fails with, or null to run it. */
    static String skipped(StudentTask task, boolean bonus) {
        String unfinished = skipBecauseOf(task, bonus);
        return unfinished == null ? null : "[" + task.label() + (bonus ? ", bonus" : "") + "] skipped: your code did not finish in "
                + unfinished + ", so this task's later tests were not run; make that test finish first" + StudentTaskRule.workOn(task);
    }

    /**
     * For the grader's test runner, before it even makes the test's object (whose fields may need
     * the very class whose static initializer never finished): the message a test of task {@code number}
     * fails with when skipped, or null to run it.
     */
    public static String skipped(int number, boolean bonus) {
        for (StudentTask task : StudentTask.values()) {
            if (task.number == number) {
                return skipped(task, bonus);
            }
        }
        return null;
    }

    /** Notes that the rule of test "Class#method" has begun: the test object was made. */
    static void entered(String test) {
        entered = test;
    }

    /** For the grader's test runner: the test ("Class#method") whose rule was entered last, or null. */
    public static String lastEntered() {
        return entered;
    }

    /**
     * For the grader's test runner: the message of a test of task {@code number} whose object was
     * never made, because making it ran student code (a static initializer, a field's value) that
     * did not finish in the unit tests' limit.
     */
    public static String stuckBeforeTheTest(int number, boolean bonus, int seconds) {
        for (StudentTask task : StudentTask.values()) {
            if (task.number == number) {
                return "[" + task.label() + (bonus ? ", bonus" : "") + "] took longer than " + seconds + " s before the test"
                        + " itself began: does a static initializer, or a field's value, in your code never finish?"
                        + StudentTaskRule.workOn(task);
            }
        }
        return null;
    }

    /**
     * Notes that {@code test} of this task did not finish in its time limit: "test Class.method", or
     * "a hidden test", as the skipped tests' messages name it.
     */
    static void didNotFinish(StudentTask task, boolean bonus, String test) {
        FIRST_UNFINISHED.putIfAbsent(key(task, bonus), test);
    }
}
