package ray.scene;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * The problems of a scene or mesh file that cannot be read at all (missing, a folder, not
 * readable), as errors located at its line 1, column 1, in words rather than as a Java exception.
 */
final class FileProblems {
    private FileProblems() {
    }

    /**
     * All bytes of {@code file}, or a {@link SceneException} saying why they cannot be read.
     *
     * @param kind what the file should be, with its article: "a scene file", "an OBJ file"
     * @param maxBytes the largest file read: a larger one is refused before any of it is read
     */
    static byte[] readAllBytes(Path file, String kind, long maxBytes) {
        checkIsFile(file, kind);
        try {
            long size = Files.size(file);
            if (size > maxBytes) {
                throw new SceneException(file, 1, 1, "the file has " + size + " bytes; expected " + kind + " of at most "
                        + maxBytes + " bytes");
            }
            return Files.readAllBytes(file);
        } catch (IOException e) {
            throw cannotRead(file, e, kind);
        }
    }

    /** Refuses a folder up front: reading one fails only later, and with the system's own words. */
    static void checkIsFile(Path file, String kind) {
        if (Files.isDirectory(file)) {
            throw new SceneException(file, 1, 1, "this is a folder; expected " + kind);
        }
    }

    /** The error for {@code e}, raised while opening or reading {@code file}. */
    static SceneException cannotRead(Path file, IOException e, String kind) {
        if (e instanceof NoSuchFileException) {
            return new SceneException(file, 1, 1, "no such file; expected the path of " + kind);
        }
        String reason = e instanceof AccessDeniedException ? "permission denied"
                // A FileSystemException's message starts with the path, which the location already gives.
                : e instanceof FileSystemException && ((FileSystemException) e).getReason() != null
                        ? ((FileSystemException) e).getReason()
                        : e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
        return new SceneException(file, 1, 1, "the file cannot be read (" + reason + "); expected " + readable(kind));
    }

    /** "a scene file" → "a readable scene file", "an OBJ file" → "a readable OBJ file". */
    private static String readable(String kind) {
        return "a readable " + kind.substring(kind.indexOf(' ') + 1);
    }
}
