package ray.testing;

import java.nio.file.Path;
import ray.accel.Acceleration;
import ray.bvh.BrokenTree;

/** Which student file threw an exception: the first frame of its stack trace outside the JDK, when it is a task's file. */
public final class StudentFrames {
    private StudentFrames() {
    }

    /**
     * The task whose file threw {@code e} itself, or null: the first frame outside the JDK must be in a
     * task's file (an IndexOutOfBoundsException from a list that Group.java indexed counts; an
     * exception the framework threw, even when a student file called it, does not, since the data
     * that upset it may come from any task), or the tree's task for the framework's check of a tree
     * ({@link BrokenTree}), whose data comes from that task's code alone.
     */
    public static StudentTask taskWhoseFileThrew(Throwable e) {
        if (e instanceof BrokenTree) {
            // The framework's check of what the tree's code returned: that code's task, though it is off the stack.
            return StudentTask.of(Acceleration.STUDENTS_TREE_TASK);
        }
        for (StackTraceElement frame : e.getStackTrace()) {
            String c = frame.getClassName();
            if (!(c.startsWith("java.") || c.startsWith("javax.") || c.startsWith("jdk.") || c.startsWith("sun.") || c.startsWith("com.sun."))) {
                return taskOf(frame);
            }
        }
        return null;
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
