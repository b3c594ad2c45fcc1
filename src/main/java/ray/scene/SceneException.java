package ray.scene;

import java.nio.file.Path;

/**
 * A mistake in a scene or mesh file, located to the file, line and column. Its message is the
 * one line a user sees: {@code FILE:LINE:COL: what is wrong; what was expected}.
 */
public class SceneException extends RuntimeException {
    private final Path file;
    private final int line;
    private final int column;
    private final String problem;

    public SceneException(Path file, int line, int column, String problem) {
        super(file + ":" + line + ":" + column + ": " + printable(problem));
        this.file = file;
        this.line = line;
        this.column = column;
        this.problem = printable(problem);
    }

    /**
     * The problem with its control characters written as Java escapes (a line break as backslash n): text quoted from a
     * damaged file must neither break the one line nor send a terminal its escape sequences.
     */
    static String printable(String problem) {
        StringBuilder s = new StringBuilder(problem.length());
        for (int i = 0; i < problem.length(); i++) {
            char c = problem.charAt(i);
            if (c == '\n') {
                s.append("\\n");
            } else if (c == '\r') {
                s.append("\\r");
            } else if (c == '\t') {
                s.append("\\t");
            } else if (Character.isISOControl(c)) {
                s.append(String.format("\\u%04x", (int) c));
            } else {
                s.append(c);
            }
        }
        return s.toString();
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

    /** The message without its location. */
    public String problem() {
        return problem;
    }
}
