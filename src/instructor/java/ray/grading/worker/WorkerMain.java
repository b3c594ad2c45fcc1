package ray.grading.worker;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayInputStream;
import java.io.FileDescriptor;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.PrintStream;

/**
 * The worker: the process that runs a student's classes during grading, as the student's user, with
 * the shipped framework and the student's files and nothing secret. It answers the judge's calls
 * over its standard input and output ({@link ray.grading.wire.Protocol}) and decides nothing: the
 * judge runs the tests and reads every answer strictly.
 *
 * <p>What the student's code prints goes to standard error, which the judge drains and keeps a little
 * of; standard output carries only the protocol, written through a stream taken before any student
 * code runs.
 */
public final class WorkerMain {
    /** Frames of this package and the wire's end a stack trace the judge is shown: below them is grading, not the student. */
    static final String OWN_PACKAGE = "ray.grading.";
    /** How the worker's own line on standard error begins when it ends on a message it could not read. */
    public static final String LAST_WORD = "ray1 worker:";

    private WorkerMain() {
    }

    public static void main(String[] args) {
        BufferedInputStream in = new BufferedInputStream(new FileInputStream(FileDescriptor.in), 1 << 16);
        BufferedOutputStream out = new BufferedOutputStream(new FileOutputStream(FileDescriptor.out), 1 << 16);
        PrintStream printed = new PrintStream(new FileOutputStream(FileDescriptor.err), true);
        System.setOut(printed);
        System.setErr(printed);
        System.setIn(new ByteArrayInputStream(new byte[0]));
        JudgeLink link = new JudgeLink(in, out);
        Runtime.getRuntime().addShutdownHook(new Thread(link::exiting, "ray1-worker-exit"));
        int status = 0;
        try {
            link.ready();
            link.serve();
        } catch (Throwable t) { // a message it could not read: the judge sees the worker end
            printed.println(LAST_WORD + " " + t);
            if (Boolean.getBoolean("ray1.worker.trace")) {
                t.printStackTrace(printed);
            }
            status = 3;
        }
        // The student's threads, if any, end with the worker (halt: no shutdown hook, this is no System.exit).
        Runtime.getRuntime().halt(status);
    }
}
