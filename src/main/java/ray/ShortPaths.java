package ray;

import java.nio.file.Path;

/** Files as the messages and pages show them: relative to the working folder when under it (as the student wrote them). */
public final class ShortPaths {
    private ShortPaths() {
    }

    /** The path relative to the working folder when the file is under it, else absolute; always with / between names. */
    public static String of(Path file) {
        Path here = Path.of("").toAbsolutePath();
        Path absolute = file.toAbsolutePath().normalize();
        return (absolute.startsWith(here) ? here.relativize(absolute) : absolute).toString().replace('\\', '/');
    }
}
