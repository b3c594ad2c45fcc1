package ray.grading.wire;

/** A message that does not follow grading's wire format: the side that sent it is not believed again. */
public final class WireError extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public WireError(String message) {
        super(message);
    }
}
