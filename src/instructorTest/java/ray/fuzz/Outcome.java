package ray.fuzz;

/** How one case ended: a render, a clean one-line error, or a failure of the framework. */
final class Outcome {
    enum Kind {
        /** The damaged scene loaded and rendered. */
        RENDERED,
        /** The damage was reported as a located one-line error. */
        ERROR,
        /** Anything else: another exception, a malformed error message, a hang, running out of memory. */
        FAILED
    }

    final Kind kind;
    /** The error's problem (RENDERED: null), or what went wrong (FAILED). */
    final String message;
    /** RENDERED: pixels whose radiance is not finite (NaN or infinite). */
    final int nonFinitePixels;
    final long nanos;

    private Outcome(Kind kind, String message, int nonFinitePixels, long nanos) {
        this.kind = kind;
        this.message = message;
        this.nonFinitePixels = nonFinitePixels;
        this.nanos = nanos;
    }

    static Outcome rendered(int nonFinitePixels, long nanos) {
        return new Outcome(Kind.RENDERED, null, nonFinitePixels, nanos);
    }

    static Outcome error(String problem, long nanos) {
        return new Outcome(Kind.ERROR, problem, 0, nanos);
    }

    static Outcome failed(String what, long nanos) {
        return new Outcome(Kind.FAILED, what, 0, nanos);
    }
}
