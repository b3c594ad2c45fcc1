package ray.assignment;

/** A table of tasks or an assignment file that cannot be used; the message is one line naming the file and what was expected. */
public final class AssignmentException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public AssignmentException(String message) {
        super(message);
    }
}
