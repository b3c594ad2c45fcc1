package ray.scene;

import java.io.IOException;
import java.io.Reader;

/**
 * Lines of text with a length limit: {@link java.io.BufferedReader#readLine} would build a string
 * of any length, so a file of a billion bytes without a line break would exhaust the heap before
 * the reader saw a single statement. Line ends are "\n", "\r\n" or "\r", as for readLine.
 */
final class BoundedLines {
    private final Reader in;
    private final int maxLength;
    private final StringBuilder line = new StringBuilder();
    private int pushedBack = -1;

    BoundedLines(Reader in, int maxLength) {
        this.in = in;
        this.maxLength = maxLength;
    }

    /** The next line without its end, or null at the end of the text. */
    String next() throws IOException, TooLong {
        line.setLength(0);
        int c = pushedBack >= 0 ? pushedBack : in.read();
        pushedBack = -1;
        if (c < 0) {
            return null;
        }
        while (c >= 0 && c != '\n' && c != '\r') {
            if (line.length() == maxLength) {
                throw new TooLong();
            }
            line.append((char) c);
            c = in.read();
        }
        if (c == '\r') {
            int after = in.read();
            if (after != '\n') {
                pushedBack = after;
            }
        }
        return line.toString();
    }

    /** The line being read has more than the allowed number of characters. */
    static final class TooLong extends Exception {
        TooLong() {
            super(null, null, false, false);
        }
    }
}
