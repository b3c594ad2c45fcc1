package ray.grading.judge;

/**
 * The judge's set-up in the process that runs the tests while grading: when the grader set up a
 * worker ({@link #WORKER_PROPERTY}), stand-ins ask it, in rounds inside a computation. The test
 * runner calls {@link #start} before the first test and {@link #stop} after the last.
 */
public final class Judge {
    /** The system property naming the grader's worker set-up, a {@link Containment} file. */
    public static final String WORKER_PROPERTY = "ray1.grading.worker";
    /** The system property with the time (milliseconds since the epoch) at which the whole grade stops. */
    public static final String DEADLINE_PROPERTY = "ray1.grading.deadline";

    private Judge() {
    }

    public static void start() {
        Rounds.installIfGrading();
    }

    /** From now on the tests are task {@code task}'s: its classes' calls go to the worker (0: none's do). */
    public static void grade(int task) {
        StudentCalls.grade(task);
    }

    /** Ends the worker, if one runs, and everything it started. */
    public static void stop() {
        Worker.stopIfStarted();
    }
}
