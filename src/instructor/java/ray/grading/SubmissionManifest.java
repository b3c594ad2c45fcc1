package ray.grading;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The MANIFEST.sha256 that the students' {@code gradle submission} (gradle/submission.gradle) packs
 * into build/submission.zip beside their files: a line {@code <sha256>  <path>} per file, as
 * sha256sum writes it. The grader takes it as part of the zip, not as a stray file to list as
 * ignored, and says in its output whether each graded file is the one that was packed. A file edited
 * or replaced after packing is graded as handed in all the same; the line tells the student, and
 * whoever reads the feedback with them, why it may not be the code they last ran.
 */
public final class SubmissionManifest {
    public static final String NAME = "MANIFEST.sha256";
    /** sha256sum's line: the hash, a space, and a space (text mode) or '*' (binary mode) before the path. */
    private static final Pattern LINE = Pattern.compile("([0-9a-fA-F]{64}) [ *](.+)");
    /** gradle submission's manifest is under a kilobyte; anything this large is no such manifest, and is not read. */
    private static final long MAX_BYTES = 64 * 1024;

    private SubmissionManifest() {
    }

    /**
     * What the grader says about the manifest, a line or two: that every graded file matches its
     * checksum, or which ones changed after packing and which the manifest does not list. Only the
     * graded files' paths (the grader's own names for them) are named, never text from the manifest.
     *
     * @param manifest the submission's MANIFEST.sha256
     * @param graded   the student files taken from the submission: project path → submitted file
     */
    public static String check(Path manifest, Map<String, Path> graded) {
        Map<String, String> listed = new LinkedHashMap<>();
        List<String> changed = new ArrayList<>();
        List<String> notListed = new ArrayList<>();
        try {
            if (Files.size(manifest) > MAX_BYTES) {
                return NAME + " is too large to be the one gradle submission writes; the files were not checked against it.\n";
            }
            for (String line : Files.readAllLines(manifest, StandardCharsets.UTF_8)) {
                if (line.isBlank()) {
                    continue;
                }
                Matcher m = LINE.matcher(line.stripTrailing());
                if (!m.matches()) {
                    return NAME + " is not as gradle submission writes it (a line \"<sha256>  <path>\" per file);"
                            + " the files were not checked against it.\n";
                }
                listed.put(m.group(2), m.group(1).toLowerCase(Locale.ROOT));
            }
            for (Map.Entry<String, Path> file : graded.entrySet()) {
                String expected = listed.get(file.getKey());
                if (expected == null) {
                    notListed.add(file.getKey());
                } else if (!expected.equals(sha256(file.getValue()))) {
                    changed.add(file.getKey());
                }
            }
        } catch (IOException | UncheckedIOException e) {
            // Not the exception's message: it would name paths of the grading machine.
            return NAME + " could not be read as text; the files were not checked against it.\n";
        }
        if (graded.isEmpty()) {
            return "";
        }
        if (changed.isEmpty() && notListed.isEmpty()) {
            return NAME + ": " + (graded.size() == 1 ? "the graded file is" : "each of the " + graded.size() + " graded files is")
                    + " the one gradle submission packed (its SHA-256 checksum matches).\n";
        }
        StringBuilder out = new StringBuilder();
        if (!changed.isEmpty()) {
            boolean one = changed.size() == 1;
            out.append(NAME).append(": ").append(String.join(", ", changed)).append(one ? " is not the file" : " are not the files")
                    .append(" gradle submission packed (").append(one ? "its SHA-256 checksum differs" : "their SHA-256 checksums differ")
                    .append(": changed after packing?); graded as handed in.\n");
        }
        if (!notListed.isEmpty()) {
            out.append(NAME).append(" does not list ").append(String.join(", ", notListed)).append(", so ")
                    .append(notListed.size() == 1 ? "it was" : "they were").append(" not checked against it.\n");
        }
        return out.toString();
    }

    /** The file's SHA-256, in lower-case hex as sha256sum writes it. */
    static String sha256(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            MessageDigest digest = MessageDigest.getInstance("SHA-256");
            byte[] buffer = new byte[8192];
            for (int n = in.read(buffer); n != -1; n = in.read(buffer)) {
                digest.update(buffer, 0, n);
            }
            return HexFormat.of().formatHex(digest.digest());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}
