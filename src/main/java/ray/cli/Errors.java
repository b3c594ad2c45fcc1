package ray.cli;

import ray.inspect.Failure;
import ray.scene.SceneException;

/** One-line descriptions of failures, for users who should not have to read a stack trace. */
final class Errors {
    private Errors() {
    }

    /** A scene file's error as it is (it names the file and line); anything else as {@link Failure} words it, with where to see more. */
    static String oneLine(Throwable e) {
        if (e instanceof SceneException) {
            return e.getMessage();
        }
        return Failure.oneLine(e, "; --verbose shows the stack trace");
    }
}
