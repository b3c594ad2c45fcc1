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
        super(file + ":" + line + ":" + column + ": " + problem);
        this.file = file;
        this.line = line;
        this.column = column;
        this.problem = problem;
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
