package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.Test;

/** The progress bar: its line, silence when not at a terminal, and a clean line when it closes. */
public class ProgressBarTest {
    @Test
    public void lineShowsTheShareAsBarAndPercent() {
        assertEquals("scene [..............................]   0%", ProgressBar.line("scene", 0));
        assertEquals("scene [###############...............]  50%", ProgressBar.line("scene", 0.5));
        // 0.999 is not yet done: the percent is floored, so 100% means finished.
        assertEquals("scene [##############################]  99%", ProgressBar.line("scene", 0.999));
        assertEquals("scene [##############################] 100%", ProgressBar.line("scene", 1));
        assertEquals("scene [..............................]   0%", ProgressBar.line("scene", -3));
    }

    @Test
    public void notAtATerminalItPrintsNothing() throws Exception {
        StringWriter text = new StringWriter();
        try (ProgressBar bar = ProgressBar.show("scene", () -> 0.5, new PrintWriter(text), false)) {
            Thread.sleep(50);
        }
        assertEquals("", text.toString());
    }

    @Test(timeout = 10_000)
    public void atATerminalItRedrawsInPlaceAndClearsItsLineWhenClosed() throws Exception {
        StringWriter text = new StringWriter();
        PrintWriter out = new PrintWriter(text);
        try (ProgressBar bar = ProgressBar.showAfter("scene", () -> 0.25, out, 0)) {
            while (!text.toString().contains("25%")) {
                Thread.sleep(10);
            }
        }
        String written = text.toString();
        assertTrue(written, written.startsWith("\rscene [########......................]  25%"));
        // Closing overwrites the bar with spaces and returns to the line's start.
        String line = ProgressBar.line("scene", 0.25);
        assertTrue(written, written.endsWith("\r" + " ".repeat(line.length()) + "\r"));
        assertTrue(written, !written.contains("\n"));
    }

    @Test
    public void aRenderThatEndsWithinTheQuietSecondDrawsNothing() {
        StringWriter text = new StringWriter();
        // A render closed within the quiet time: a minute here, so that a loaded machine cannot make
        // the empty block below outlast it (ProgressBar.QUIET_MILLIS is a second).
        try (ProgressBar bar = ProgressBar.showAfter("scene", () -> 1, new PrintWriter(text), 60_000)) {
            // a quick render
        }
        assertEquals("", text.toString());
    }
}
