package ray.grading.judge;

/**
 * The worker did not answer a call as a worker must: it ended (System.exit, a crash, running out of
 * memory), answered out of format, or took too long. The call's test fails with this message; the
 * worker is ended and the next call starts another.
 */
public final class WorkerFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** What happened, for the messages that differ. */
    public enum Kind { ENDED, EXITED, TIMED_OUT, GARBLED }

    public final Kind kind;

    WorkerFailure(String message) {
        this(Kind.GARBLED, message);
    }

    WorkerFailure(Kind kind, String message) {
        super(message);
        this.kind = kind;
    }
}
