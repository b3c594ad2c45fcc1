package ray.testing;

import java.nio.file.Path;
import ray.testing.StudentTask;

/** Which student file an exception came from: the first frame of its stack trace in a task's file. */
public final class StudentFrames {
    private StudentFrames() {
    }

    /** The task whose file holds the deepest frame of {@code e} in any task's file, or null. */
    public static StudentTask taskThatThrew(Throwable e) {
        for (StackTraceElement frame : e.getStackTrace()) {
            StudentTask task = taskOf(frame);
            if (task != null) {
                return task;
            }
        }
        return null;
    }

    /** " at Sphere.java:57" for that frame, or "" when no task's file is on the stack. */
    public static String where(Throwable e) {
        for (StackTraceElement frame : e.getStackTrace()) {
            if (taskOf(frame) != null) {
                return " at " + frame.getFileName() + ":" + frame.getLineNumber();
            }
        }
        return "";
    }

    private static StudentTask taskOf(StackTraceElement frame) {
        if (frame.getFileName() == null) {
            return null;
        }
        String className = frame.getClassName().replace('.', '/');
        int nested = className.indexOf('$');
        String source = "src/main/java/" + (nested < 0 ? className : className.substring(0, nested)) + ".java";
        for (StudentTask task : StudentTask.values()) {
            for (String file : task.files) {
                if (Path.of(file).equals(Path.of(source))) {
                    return task;
                }
            }
        }
        return null;
    }
}
