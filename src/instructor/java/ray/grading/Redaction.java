package ray.grading;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Keeps the grader's own files out of what a student sees. Isolated ({@link Sandbox}), student code
 * cannot read them at all; without isolation (a grader not running as root) it can, so a submission
 * could throw the text of a hidden test or of the solution as an exception's message, which a
 * failure report would then quote. Every line of a
 * result that quotes a line found only in the instructor's files (src/instructor, src/instructorTest,
 * and the solution blocks of the student files) has that quotation replaced; lines the handout ships too (an
 * import, a closing brace) are common knowledge and stay, as do lines too short to identify anything.
 */
final class Redaction {
    /** Lines shorter than this (trimmed) say too little to give anything away ("}", "return t;"). */
    static final int SHORTEST_SECRET = 16;
    static final String REMOVED = "[removed: a quotation of the grader's own files]";

    private final List<String> secrets;

    private Redaction(List<String> secrets) {
        this.secrets = secrets;
    }

    /** The secrets of the instructor's project at {@code project}. */
    static Redaction of(Path project) {
        Set<String> shipped = new HashSet<>();
        Set<String> secret = new HashSet<>();
        try {
            for (Path file : filesUnder(project, "src/main/java", "src/test/java")) {
                String text = Files.readString(file, StandardCharsets.UTF_8);
                String relative = project.relativize(file).toString().replace('\\', '/');
                if (text.contains(SolutionMarkers.BEGIN)) {
                    addLines(SolutionMarkers.studentVersion(text, relative), shipped);
                    addLines(text, secret); // the whole file; what the student version also has is removed below
                } else {
                    addLines(text, shipped);
                }
            }
            for (Path file : filesUnder(project, "src/instructor", "src/instructorTest")) {
                addLines(Files.readString(file, StandardCharsets.UTF_8), secret);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        secret.removeAll(shipped);
        return new Redaction(new ArrayList<>(secret));
    }

    /** {@code text} with every quotation of a secret line replaced by {@link #REMOVED}. */
    String redact(String text) {
        if (text == null || text.isEmpty()) {
            return text;
        }
        StringBuilder out = new StringBuilder(text.length());
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            out.append(withoutSecrets(lines[i]));
            if (i < lines.length - 1) {
                out.append('\n');
            }
        }
        return out.toString();
    }

    /** Each outcome with its message redacted. */
    List<TestOutcome> redact(List<TestOutcome> outcomes) {
        List<TestOutcome> out = new ArrayList<>(outcomes.size());
        for (TestOutcome t : outcomes) {
            String message = redact(t.message());
            out.add(message.equals(t.message()) ? t : new TestOutcome(t.id(), t.className(), t.method(), t.task(), t.taskTitle(),
                    t.points(), t.bonus(), t.visibility(), t.passed(), message, t.seconds()));
        }
        return out;
    }

    /** The line with each secret line it quotes replaced, so that what the student's code did around it still reads. */
    private String withoutSecrets(String line) {
        if (line.strip().length() < SHORTEST_SECRET) {
            return line;
        }
        String out = line;
        for (String secret : secrets) {
            if (out.contains(secret)) {
                out = out.replace(secret, REMOVED);
            }
        }
        return out;
    }

    private static void addLines(String text, Set<String> into) {
        for (String line : text.split("\n")) {
            String trimmed = line.strip();
            if (trimmed.length() >= SHORTEST_SECRET) {
                into.add(trimmed);
            }
        }
    }

    private static List<Path> filesUnder(Path project, String... folders) throws IOException {
        List<Path> files = new ArrayList<>();
        for (String folder : folders) {
            Path root = project.resolve(folder);
            if (Files.isDirectory(root)) {
                try (Stream<Path> walk = Files.walk(root)) {
                    files.addAll(walk.filter(Files::isRegularFile).filter(p -> isText(p.toString())).collect(Collectors.toList()));
                }
            }
        }
        return files;
    }

    private static boolean isText(String name) {
        return name.endsWith(".java") || name.endsWith(".txt") || name.endsWith(".xml") || name.endsWith(".properties")
                || name.endsWith(".sh") || name.contains("META-INF");
    }
}
