package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertThrows;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import org.junit.Assume;
import org.junit.rules.TemporaryFolder;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Helpers shared by the scene tests (this class holds no tests): write scene and OBJ text into a
 * temporary folder, load it, intersect the loaded surfaces, and check where an error points.
 */
final class SceneFixtures {
    /** A camera and an image size, the two things every loadable scene needs. */
    static final String CAMERA_AND_IMAGE = "  <camera type=\"PerspectiveCamera\"/>\n  <image>4 3</image>\n";

    private SceneFixtures() {
    }

    /** Writes {@code text} (UTF-8) to {@code relativePath} under the folder, creating subfolders. */
    static Path write(TemporaryFolder folder, String relativePath, String text) {
        return write(folder, relativePath, text.getBytes(StandardCharsets.UTF_8));
    }

    /** Writes {@code bytes} to {@code relativePath} under the folder, creating subfolders. */
    static Path write(TemporaryFolder folder, String relativePath, byte[] bytes) {
        try {
            Path file = folder.getRoot().toPath().resolve(relativePath);
            Files.createDirectories(file.getParent());
            Files.write(file, bytes);
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Makes {@code file} unreadable and returns the reason the loader will give. Taking every
     * permission away does it for an ordinary user ("permission denied"); root reads any file, so
     * there (and on a file system without POSIX permissions) the file becomes a link to Linux's
     * /proc/self/mem, whose first page no process can read ("Input/output error"). Where neither
     * works the calling test is skipped (an assumption failure).
     */
    static String makeUnreadable(Path file) {
        try {
            Files.setPosixFilePermissions(file, Set.of());
            if (!Files.isReadable(file)) {
                return "permission denied";
            }
        } catch (UnsupportedOperationException | IOException e) {
            // no POSIX permissions here: try the other way
        }
        Path memory = Path.of("/proc/self/mem");
        Assume.assumeTrue("no way to make a file unreadable here", Files.exists(memory));
        try {
            Files.delete(file);
            Files.createSymbolicLink(file, memory);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return "Input/output error";
    }

    /** Loads a scene whose {@code <scene>} holds a camera, an image size and then {@code body}. */
    static Scene loadBody(TemporaryFolder folder, String body) {
        return SceneLoader.load(write(folder, "scene.xml", "<scene>\n" + CAMERA_AND_IMAGE + body + "</scene>\n"));
    }

    /** Loads the complete scene text {@code xml}, written to scene.xml. */
    static Scene loadText(TemporaryFolder folder, String xml) {
        return SceneLoader.load(write(folder, "scene.xml", xml));
    }

    /** The error that loading {@code file} must raise. */
    static SceneException loadError(Path file) {
        return assertThrows(SceneException.class, () -> SceneLoader.load(file));
    }

    /** The error that loading the complete scene text {@code xml} (written to bad.xml) must raise. */
    static SceneException loadError(TemporaryFolder folder, String xml) {
        return loadError(write(folder, "bad.xml", xml));
    }

    /**
     * Checks that the error names {@code file} at {@code line}:{@code column} in both its fields and its
     * message, and that its message is exactly the one line "FILE:LINE:COL: problem".
     */
    static void assertError(SceneException e, Path file, int line, int column, String problem) {
        String where = "error \"" + e.getMessage() + "\"";
        assertEquals(where + ": file", file, e.file());
        assertEquals(where + ": line", line, e.line());
        assertEquals(where + ": column", column, e.column());
        assertEquals(file + ":" + line + ":" + column + ": " + problem, e.getMessage());
        assertFalse(where + " is one line", e.getMessage().contains("\n") || e.getMessage().contains("\r"));
    }

    /** The closest hit of the ray origin + t·direction (t > 0) among the scene's surfaces, or null for a miss. */
    static IntersectionRecord hit(Scene scene, Vec3 origin, Vec3 direction) {
        IntersectionRecord record = new IntersectionRecord();
        return scene.getSurfaces().intersect(record, new Ray(origin, direction)) ? record : null;
    }
}
