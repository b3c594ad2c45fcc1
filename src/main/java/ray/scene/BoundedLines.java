package ray.scene;

import java.io.IOException;
import java.io.Reader;

/**
 * Lines of text with a length limit: {@link java.io.BufferedReader#readLine} would build a string
 * of any length, so a file of a billion bytes without a line break would exhaust the heap before
 * the reader saw a single statement. Line ends are "\n", "\r\n" or "\r", as for readLine.
 *
 * <p>Reads the text in blocks into its own buffer: reading a char at a time from a Reader (one
 * synchronized call each) doubled the time to load a mesh.
 */
final class BoundedLines {
    private final Reader in;
    private final int maxLength;
    private final StringBuilder line = new StringBuilder();
    private final char[] buffer = new char[8192];
    private int position;
    private int end;
    /** The last line ended with "\r": a "\n" right after it belongs to that line end. */
    private boolean afterReturn;

    BoundedLines(Reader in, int maxLength) {
        this.in = in;
        this.maxLength = maxLength;
    }

    /** The next line without its end, or null at the end of the text. */
    String next() throws IOException, TooLong {
        line.setLength(0);
        if (!fill()) {
            return null;
        }
        if (afterReturn) {
            afterReturn = false;
            if (buffer[position] == '\n') {
                position++;
                if (!fill()) {
                    return null;
                }
            }
        }
        while (fill()) {
            int start = position;
            while (position < end && buffer[position] != '\n' && buffer[position] != '\r') {
                position++;
            }
            if (line.length() + (position - start) > maxLength) {
                throw new TooLong();
            }
            line.append(buffer, start, position - start);
            if (position < end) {
                afterReturn = buffer[position] == '\r';
                position++;
                return line.toString();
            }
        }
        return line.toString();
    }

    /** Whether a char is ready at {@code position}, reading the next block when the buffer is used up. */
    private boolean fill() throws IOException {
        while (position == end) {
            int n = in.read(buffer, 0, buffer.length);
            if (n < 0) {
                return false;
            }
            position = 0;
            end = n;
        }
        return true;
    }

    /** The line being read has more than the allowed number of characters. */
    static final class TooLong extends Exception {
        TooLong() {
            super(null, null, false, false);
        }
    }
}
