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
final class UnfinishedTasks {
    static final String SKIP_PROPERTY = "ray1.grading.skipAfterTimeout";
    static final String EARLIER_PROPERTY = "ray1.grading.unfinished";
    private static final Map<String, String> FIRST_UNFINISHED = new ConcurrentHashMap<>();

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

    /**
     * Notes that {@code test} of this task did not finish in its time limit: "test Class.method", or
     * "a hidden test", as the skipped tests' messages name it.
     */
    static void didNotFinish(StudentTask task, boolean bonus, String test) {
        FIRST_UNFINISHED.putIfAbsent(key(task, bonus), test);
    }
}
