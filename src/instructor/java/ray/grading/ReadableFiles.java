package ray.grading;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * Files written through a temporary file (so that they appear whole or not at all) inherit its
 * mode, 0600: a results.json or a handout zip that only its writer can read. Those are meant to be
 * read by others (the platform's harness, a course page), so they are made 0644 where the file
 * system has POSIX permissions.
 */
public final class ReadableFiles {
    private ReadableFiles() {
    }

    /** Makes {@code file} readable by everyone and writable by its owner (0644); a no-op without POSIX permissions. */
    public static void makeReadable(Path file) throws IOException {
        if (Files.getFileAttributeView(file, PosixFileAttributeView.class) != null) {
            Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-r--r--"));
        }
    }
}
