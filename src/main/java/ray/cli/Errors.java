package ray.cli;

import ray.scene.SceneException;

/** One-line descriptions of failures, for users who should not have to read a stack trace. */
final class Errors {
    private Errors() {
    }

    static String oneLine(Throwable e) {
        if (e instanceof SceneException) {
            return e.getMessage();
        }
        if (e instanceof ray.bvh.BrokenTree) {
            return ((ray.bvh.BrokenTree) e).inOneLine();
        }
        String message = e.getClass().getSimpleName() + (e.getMessage() != null ? ": " + e.getMessage() : "");
        for (StackTraceElement frame : e.getStackTrace()) {
            if (frame.getClassName().startsWith("ray.")) {
                return message + " (at " + frame.getFileName() + ":" + frame.getLineNumber() + "; --verbose shows the stack trace)";
            }
        }
        return message;
    }
}
