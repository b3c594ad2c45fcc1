package ray.scene;

/**
 * The end tag the parser stopped in, read from the file's text: the last "&lt;/" on the parser's
 * line up to where it stopped, and the name after it. (A class, not a record: Gradle 4.4 cannot
 * read a record's class file on the compile classpath.)
 */
final class FoundEndTag {
    /** The name as written, up to the '>' or white space. */
    final String name;
    /** Where its "&lt;/" starts. */
    final int line;
    final int column;

    private FoundEndTag(String name, int line, int column) {
        this.name = name;
        this.line = line;
        this.column = column;
    }

    /**
     * The end tag at or before {@code line}:{@code column} on that line, or null if the line has none
     * there or only a bare "&lt;/" (as at the end of a cut-off file).
     */
    static FoundEndTag at(TextPositions positions, int line, int column) {
        String text = positions.text();
        int lineStart = positions.offset(line, 1);
        int start = text.lastIndexOf("</", positions.offset(line, column));
        if (start < lineStart) {
            return null;
        }
        int end = start + 2;
        while (end < text.length() && text.charAt(end) != '>' && !Character.isWhitespace(text.charAt(end))) {
            end++;
        }
        if (end == start + 2) {
            return null;
        }
        int[] where = positions.position(start);
        return new FoundEndTag(text.substring(start + 2, end), where[0], where[1]);
    }
}
