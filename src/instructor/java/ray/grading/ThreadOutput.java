package ray.grading;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;

/**
 * System.out and System.err routed by thread: graders that run at once in one JVM print to
 * System.out, and each one's lines belong in its own log, not interleaved on the console. A
 * thread (and the threads it starts) writes where {@link #route} sent it; any other thread writes
 * to the original stream.
 */
public final class ThreadOutput extends OutputStream {
    private final OutputStream fallback;
    private final InheritableThreadLocal<OutputStream> target = new InheritableThreadLocal<>();

    private ThreadOutput(OutputStream fallback) {
        this.fallback = fallback;
    }

    /** Installs a routing System.out and System.err; returns the original System.err (for progress lines). */
    public static PrintStream install() {
        PrintStream err = System.err;
        if (!(System.out instanceof Routed)) {
            System.setOut(new Routed(new ThreadOutput(System.out)));
            System.setErr(new Routed(new ThreadOutput(err)));
        }
        return err instanceof Routed r ? (PrintStream) r.output().fallback : err;
    }

    /** Sends this thread's (and its children's) System.out and System.err to {@code to}, or back when null. */
    public static void route(OutputStream to) {
        for (PrintStream s : new PrintStream[] {System.out, System.err}) {
            if (s instanceof Routed r) {
                s.flush();
                if (to == null) {
                    r.output().target.remove();
                } else {
                    r.output().target.set(to);
                }
            }
        }
    }

    private OutputStream current() {
        OutputStream t = target.get();
        return t == null ? fallback : t;
    }

    @Override
    public void write(int b) throws IOException {
        current().write(b);
    }

    @Override
    public void write(byte[] b, int off, int len) throws IOException {
        current().write(b, off, len);
    }

    @Override
    public void flush() throws IOException {
        current().flush();
    }

    /** The PrintStream that routes, so that installing twice does not route through itself. */
    private static final class Routed extends PrintStream {
        Routed(ThreadOutput out) {
            super(out, true);
        }

        ThreadOutput output() {
            return (ThreadOutput) out;
        }
    }
}
