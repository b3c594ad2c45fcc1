package ray.inspect;

/** An exception in one line, with the place in the project's code that threw it. */
public final class Failure {
    private Failure() {
    }

    /**
     * "NullPointerException: … (at Sphere.java:57)": the first frame in package ray is the code to look
     * at; a tree the framework cannot search with names the students' tree ({@link ray.bvh.BrokenTree#inOneLine}).
     */
    public static String oneLine(Throwable e) {
        return oneLine(e, "");
    }

    /** As {@link #oneLine(Throwable)}, with {@code more} after the place ("; --verbose shows the stack trace"). */
    public static String oneLine(Throwable e, String more) {
        if (e instanceof ray.bvh.BrokenTree) {
            return ((ray.bvh.BrokenTree) e).inOneLine();
        }
        String message = e.getClass().getSimpleName() + (e.getMessage() != null ? ": " + e.getMessage() : "");
        for (StackTraceElement frame : e.getStackTrace()) {
            if (frame.getClassName().startsWith("ray.")) {
                return message + " (at " + frame.getFileName() + ":" + frame.getLineNumber() + more + ")";
            }
        }
        return message;
    }
}
