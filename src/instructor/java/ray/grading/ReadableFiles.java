package ray.grading;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
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

    /** Writes {@code text} through a temporary file beside it (so it appears whole or not at all), readable by all. */
    public static void writeAtomically(Path file, String text) throws IOException {
        Path folder = file.toAbsolutePath().getParent();
        Files.createDirectories(folder);
        Path temporary = Files.createTempFile(folder, "." + file.getFileName(), ".tmp");
        try {
            Files.writeString(temporary, text, StandardCharsets.UTF_8);
            Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING);
            makeReadable(file);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }
}
