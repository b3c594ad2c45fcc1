package ray.fuzz;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import ray.scene.SceneException;

/** The checks a user-facing error must pass: the format {@code FILE:LINE:COL: what is wrong; what was expected}. */
final class ErrorFormat {
    private ErrorFormat() {
    }

    /** What is wrong with the error's form, or null when it is well formed. */
    static String problemWith(SceneException e, Path sceneFile) {
        String message = e.getMessage();
        if (message.indexOf('\n') >= 0 || message.indexOf('\r') >= 0) {
            return "more than one line";
        }
        if (!message.equals(e.file() + ":" + e.line() + ":" + e.column() + ": " + e.problem())) {
            return "not FILE:LINE:COL: problem";
        }
        if (e.line() < 1 || e.column() < 1) {
            return "line or column below 1";
        }
        Path file = e.file();
        if (!file.equals(sceneFile) && !Files.isRegularFile(file)) {
            return "names neither the scene nor an existing file";
        }
        if (Files.isRegularFile(file) && e.line() > lineCount(file)) {
            return "line " + e.line() + " is past the end of the file";
        }
        if (!e.problem().contains("expected")) {
            return "does not say what was expected";
        }
        return null;
    }

    private static long lineCount(Path file) {
        try {
            byte[] bytes = Files.readAllBytes(file);
            // The lines an error can point at: one more than the line breaks, the last one maybe empty (where the file ends).
            long lines = 1;
            for (int i = 0; i < bytes.length; i++) {
                // "\n", "\r\n" and a lone "\r" each end a line, as the XML parser counts them.
                boolean loneReturn = bytes[i] == '\r' && (i + 1 == bytes.length || bytes[i + 1] != '\n');
                lines += bytes[i] == '\n' || loneReturn ? 1 : 0;
            }
            return lines;
        } catch (IOException e) {
            return Long.MAX_VALUE;
        }
    }
}
