package ray.grading;

import java.io.PrintStream;
import java.util.Locale;

/**
 * "graded 12 / 80, 3 skipped, ETA 4 min 10 s" on stderr. At a terminal one line is rewritten in
 * place, at most once a second; into a log (not a terminal) each update is a line of its own. The
 * ETA counts only submissions graded in this run: skipped ones (already graded) take no time.
 */
public final class Progress {
    private final PrintStream err;
    private final boolean terminal;
    private final int total;
    private final long start = System.nanoTime();
    private int graded;
    private int skipped;
    private long lastShown = Long.MIN_VALUE;

    public Progress(PrintStream err, boolean terminal, int total) {
        this.err = err;
        this.terminal = terminal;
        this.total = total;
    }

    public synchronized void skipped() {
        skipped++;
        show(false);
    }

    public synchronized void graded() {
        graded++;
        show(false);
    }

    /** At a terminal, the final state (the last update may have been too soon to show), and the line ended. */
    public synchronized void finish() {
        if (terminal) {
            show(true);
            err.println();
        }
    }

    private void show(boolean always) {
        long now = System.nanoTime();
        if (terminal && !always && now - lastShown < 1_000_000_000L) {
            return;
        }
        lastShown = now;
        String line = line(now);
        if (terminal) {
            err.print("\r" + line + "   ");
            err.flush();
        } else {
            err.println(line);
        }
    }

    String line(long now) {
        int done = graded + skipped;
        int left = total - done;
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "graded %d / %d", done, total));
        if (skipped > 0) {
            s.append(", ").append(skipped).append(" skipped (already graded)");
        }
        if (left > 0 && graded > 0) {
            // Submissions finish in parallel, so elapsed time per finished one already counts the jobs.
            s.append(", ETA ").append(duration((now - start) / 1e9 / graded * left));
        }
        return s.toString();
    }

    public static String duration(double seconds) {
        long s = Math.round(seconds);
        return s < 60 ? s + " s" : s < 3600 ? s / 60 + " min " + s % 60 + " s" : s / 3600 + " h " + s % 3600 / 60 + " min";
    }
}
