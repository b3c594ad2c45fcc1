package ray.scene;

import java.nio.file.Path;
import java.util.Locale;

/**
 * A mistake in a scene or mesh file, located to the file, line and column. Its message is the
 * one line a user sees: {@code FILE:LINE:COL: what is wrong; what was expected}.
 */
public class SceneException extends RuntimeException {
    private final Path file;
    private final int line;
    private final int column;
    private final String problem;

    /** {@code problem} is put on one line (see {@link #oneLine}), whatever it quotes from the file. */
    public SceneException(Path file, int line, int column, String problem) {
        super(located(file, line, column, oneLine(problem)));
        this.file = file;
        this.line = line;
        this.column = column;
        this.problem = oneLine(problem);
    }

    public Path file() {
        return file;
    }

    public int line() {
        return line;
    }

    public int column() {
        return column;
    }

    /**
     * The message with the file named as {@code shownFile} (a path relative to the project, say,
     * where the file was read by its absolute path).
     */
    public String messageNaming(Path shownFile) {
        return located(shownFile, line, column, problem);
    }

    /** {@code FILE:LINE:COL: text}, the form of every located line (errors, and the loader's warnings). */
    static String located(Path file, int line, int column, String problem) {
        return file + ":" + line + ":" + column + ": " + problem;
    }

    /** The message without its location. */
    public String problem() {
        return problem;
    }

    /**
     * {@code text} as one line: each run of white space (line breaks and tabs included) becomes one
     * space, and any other control character or line separator is written as a backslash, "u" and
     * its four hex digits, so that a quoted piece of a file cannot break the message in two.
     */
    static String oneLine(String text) {
        StringBuilder out = new StringBuilder(text.length());
        boolean inSpace = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            boolean space = c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\u000B';
            if (space) {
                if (!inSpace) {
                    out.append(' ');
                }
            } else if (Character.isISOControl(c) || c == '\u2028' || c == '\u2029') {
                out.append(String.format(Locale.ROOT, "\\u%04X", (int) c));
            } else {
                out.append(c);
            }
            inSpace = space;
        }
        return out.toString();
    }

    /** A piece of a file to quote in a message: on one line, and cut to 40 characters. */
    static String excerpt(String text) {
        String s = oneLine(text);
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
