package ray.cli;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.function.DoubleSupplier;

/**
 * A one-line progress bar on the console for renders that take a while: nothing for the first
 * second (most scenes are done by then), then "name [#####.....]  45%" redrawn in place every
 * tenth of a second, and the line cleared at the end. Quiet when the output is not a terminal, so
 * logs and pipes never see carriage returns. It only reads a progress figure from its own daemon
 * thread; the render loop does not wait for it.
 */
final class ProgressBar implements AutoCloseable {
    static final long QUIET_MILLIS = 1000;
    static final long REDRAW_MILLIS = 100;
    private static final int WIDTH = 30;

    private final Thread thread;
    private final PrintWriter out;
    private volatile boolean done;
    private volatile boolean drawn;
    private volatile int lastLength;

    /** @param quietMillis how long to wait before drawing, or a negative number for a bar that never draws */
    private ProgressBar(String label, DoubleSupplier progress, PrintWriter out, long quietMillis) {
        this.out = out;
        if (quietMillis < 0) {
            this.thread = null;
            return;
        }
        this.thread = new Thread(() -> run(label, progress, quietMillis), "progress");
        thread.setDaemon(true);
        thread.start();
    }

    /** Shows progress on {@code out} if {@code terminal}; otherwise a bar that does nothing. */
    static ProgressBar show(String label, DoubleSupplier progress, PrintWriter out, boolean terminal) {
        return new ProgressBar(label, progress, out, terminal ? QUIET_MILLIS : -1);
    }

    /** For tests: a bar that starts drawing after {@code quietMillis}. */
    static ProgressBar showAfter(String label, DoubleSupplier progress, PrintWriter out, long quietMillis) {
        return new ProgressBar(label, progress, out, quietMillis);
    }

    /** "name [###########...................]  37%". */
    static String line(String label, double progress) {
        double p = Math.max(0, Math.min(1, progress));
        int filled = (int) Math.round(p * WIDTH);
        return String.format(Locale.ROOT, "%s [%s%s] %3d%%", label, "#".repeat(filled), ".".repeat(WIDTH - filled),
                (int) Math.floor(p * 100));
    }

    private void run(String label, DoubleSupplier progress, long quietMillis) {
        try {
            Thread.sleep(quietMillis);
            while (!done) {
                String text = line(label, progress.getAsDouble());
                synchronized (out) {
                    if (done) {
                        return;
                    }
                    out.print("\r" + text);
                    out.flush();
                    drawn = true;
                    lastLength = text.length();
                }
                Thread.sleep(REDRAW_MILLIS);
            }
        } catch (InterruptedException e) {
            // closed while waiting
        }
    }

    /** Stops drawing and clears the bar's line, so the next output starts on a clean line. */
    @Override
    public void close() {
        done = true;
        if (thread == null) {
            return;
        }
        thread.interrupt();
        synchronized (out) {
            if (drawn) {
                out.print("\r" + " ".repeat(lastLength) + "\r");
                out.flush();
            }
        }
    }
}
