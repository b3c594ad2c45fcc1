package ray.testing;

/**
 * A test failure whose cause lies outside the code of the test's own task: a broken scene file, or
 * another task that is still unfinished. {@link StudentTaskRule} reports it under the test's task
 * (that is where its points are counted) but does not tell the student to work on that task.
 */
public final class NotThisTasksFault extends AssertionError {
    private static final long serialVersionUID = 1L;

    public NotThisTasksFault(String message) {
        super(message);
    }
}
