package ray.testing;

import ray.assignment.Assignment;
import ray.assignment.HintLevel;

/**
 * How much a failure message may say, by the hint level of the running test's task (the
 * assignment's {@code hints}): at {@code goal} a message says what was expected and what came back,
 * never the fix or a formula of the solution; at {@code steps} it may say what went wrong in words;
 * at {@code formulas} it may give the formula too.
 */
public final class Hints {
    /** The task of the test running now ({@link StudentTaskRule} sets it; tests of one JVM run one at a time). */
    private static volatile StudentTask running;

    private Hints() {
    }

    static void running(StudentTask task) {
        running = task;
    }

    /** The running test's task's hint level ({@code formulas} outside a graded test). */
    public static HintLevel level() {
        StudentTask task = running;
        return task == null ? HintLevel.FORMULAS : Assignment.current().hints(task.id);
    }

    /** Whether a message may name a likely cause and its fix: not at {@code goal}. */
    public static boolean fixesShown() {
        return level() != HintLevel.GOAL;
    }

    /** {@code fix} where fixes are shown, else "". */
    public static String fix(String fix) {
        return fixesShown() ? fix : "";
    }

    /** The formula at {@code formulas}, its statement in words below that. */
    public static String wordsOrFormula(String words, String formula) {
        return level() == HintLevel.FORMULAS ? formula : words;
    }
}
