package ray.scene;

import java.util.Arrays;

/**
 * Line and column of a place in a scene file's text, and back, counted as the XML parser counts them:
 * "\n", "\r\n" and a lone "\r" each end a line, each char is one column, and a byte order mark at the
 * start is not counted. The parser reports only where it stopped; an error that points where
 * something starts (an unclosed element, comment or end tag) finds that place in the text.
 */
final class TextPositions {
    private static final char BYTE_ORDER_MARK = '\uFEFF';
    private final String text;
    /** The offset of each line's first char: lineStarts[0] is line 1's. */
    private final int[] lineStarts;

    TextPositions(String fileText) {
        text = fileText.startsWith(String.valueOf(BYTE_ORDER_MARK)) ? fileText.substring(1) : fileText;
        int[] starts = new int[16];
        int lines = 1;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            boolean lineEnd = c == '\n' || (c == '\r' && (i + 1 == text.length() || text.charAt(i + 1) != '\n'));
            if (lineEnd) {
                if (lines == starts.length) {
                    starts = Arrays.copyOf(starts, 2 * lines);
                }
                starts[lines++] = i + 1;
            }
        }
        lineStarts = Arrays.copyOf(starts, lines);
    }

    /** The text the positions count in (without a byte order mark). */
    String text() {
        return text;
    }

    /** The offset of {@code line}:{@code column}, kept within the text, and within the line when the column is past its end. */
    int offset(int line, int column) {
        if (line > lineStarts.length) {
            return text.length();
        }
        int start = lineStarts[Math.max(line, 1) - 1];
        int end = line < lineStarts.length ? lineStarts[line] : text.length();
        // The line's break ("\n", "\r" or "\r\n") is not part of it.
        while (end > start && (text.charAt(end - 1) == '\n' || text.charAt(end - 1) == '\r')) {
            end--;
        }
        return Math.min(start + Math.max(column, 1) - 1, end);
    }

    /** {line, column} of the char at {@code offset}. */
    int[] position(int offset) {
        int found = Arrays.binarySearch(lineStarts, offset);
        // Not a line's first char: binarySearch gives -(the next line's index) - 1.
        int lineIndex = found >= 0 ? found : -found - 2;
        return new int[] {lineIndex + 1, offset - lineStarts[lineIndex] + 1};
    }
}
