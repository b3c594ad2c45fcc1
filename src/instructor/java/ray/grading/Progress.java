package ray.grading;

import java.io.PrintStream;
import java.util.Locale;

/**
 * "graded 12 / 80, 3 skipped, ETA 4 min 10 s" on stderr, and how long each submission took. Into a
 * log (not a terminal) each update is a line of its own, naming the submission just graded and its
 * seconds ("graded 12 / 80: submission_12 in 9.8 s, ETA 4 min 10 s"); at a terminal each graded
 * submission gets a line ("submission_12 graded in 9.8 s") and the progress is one line below,
 * rewritten in place at most once a second. The ETA counts only submissions graded in this run:
 * skipped ones (already graded) take no time.
 */
public final class Progress {
    private final PrintStream err;
    private final boolean terminal;
    private final int total;
    private final long start = System.nanoTime();
    private int graded;
    private int skipped;
    private long lastShown = Long.MIN_VALUE;
    /** How wide the line at the terminal is, to blank it out under a shorter one. */
    private int shownWidth;

    public Progress(PrintStream err, boolean terminal, int total) {
        this.err = err;
        this.terminal = terminal;
        this.total = total;
    }

    public synchronized void skipped() {
        skipped++;
        show(false);
    }

    /** {@code id} was graded in this run, in {@code seconds}. */
    public synchronized void graded(String id, double seconds) {
        graded++;
        String done = id + " in " + seconds(seconds);
        if (terminal) {
            // Its own line over the progress line, which then comes back below it.
            String line = done.replaceFirst(" in ", " graded in ");
            err.print("\r" + line + " ".repeat(Math.max(0, shownWidth - line.length())) + "\n");
            show(true);
        } else {
            lastShown = System.nanoTime();
            err.println(line(lastShown, done));
        }
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
        String line = line(now, null);
        if (terminal) {
            err.print("\r" + line + "   ");
            err.flush();
            shownWidth = line.length() + 3;
        } else {
            err.println(line);
        }
    }

    /** The progress, with {@code last} ("submission_12 in 9.8 s") after the count when not null. */
    private String line(long now, String last) {
        int done = graded + skipped;
        int left = total - done;
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "graded %d / %d", done, total));
        if (last != null) {
            s.append(": ").append(last);
        }
        if (skipped > 0) {
            s.append(", ").append(skipped).append(" skipped (already graded)");
        }
        if (left > 0 && graded > 0) {
            // Submissions finish in parallel, so elapsed time per finished one already counts the jobs.
            s.append(", ETA ").append(duration((now - start) / 1e9 / graded * left));
        }
        return s.toString();
    }

    /** A grading's time as the log and the summary give it: "9.8 s". */
    public static String seconds(double seconds) {
        return String.format(Locale.ROOT, "%.1f s", seconds);
    }

    public static String duration(double seconds) {
        long s = Math.round(seconds);
        return s < 60 ? s + " s" : s < 3600 ? s / 60 + " min " + s % 60 + " s" : s / 3600 + " h " + s % 3600 / 60 + " min";
    }
}
