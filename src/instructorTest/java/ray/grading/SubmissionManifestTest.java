package ray.grading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The MANIFEST.sha256 of {@code gradle submission}'s zip: taken with the submission, never listed as
 * an ignored file, and checked against the graded files, with one line saying how they compare.
 * (SubmissionZipTest packs and grades a real zip.)
 */
public class SubmissionManifestTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final String SPHERE = "src/main/java/ray/surface/Sphere.java";
    private static final String GROUP = "src/main/java/ray/surface/Group.java";
    private static final List<String> WANTED = List.of(SPHERE, GROUP);

    private static String sha256(String text) throws Exception {
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
    }

    /** A submission folder: each file at its path under {@code top} with the given text. */
    private Path submission(String top, Map<String, String> files) throws Exception {
        Path root = folder.newFolder().toPath();
        for (Map.Entry<String, String> f : files.entrySet()) {
            Path file = root.resolve(top).resolve(f.getKey());
            Files.createDirectories(file.getParent());
            Files.writeString(file, f.getValue(), StandardCharsets.UTF_8);
        }
        return root;
    }

    private Submission locate(Path root) throws Exception {
        return Submission.locate(root, WANTED, folder.getRoot().toPath().resolve("unpacked"));
    }

    @Test
    public void theManifestIsTakenNotIgnoredAndMatchingFilesSaySo() throws Exception {
        String manifest = sha256("sphere") + "  " + SPHERE + "\n" + sha256("group") + "  " + GROUP + "\n";
        for (String top : List.of("", "ray1/")) {
            Path root = submission(top, Map.of(SPHERE, "sphere", GROUP, "group", "MANIFEST.sha256", manifest));
            Submission s = locate(root);
            assertEquals(List.of(), s.ignored);
            assertEquals(root.resolve(top + "MANIFEST.sha256"), s.manifest);
            assertEquals("MANIFEST.sha256: each of the 2 graded files is the one gradle submission packed (its SHA-256 checksum matches).\n",
                    SubmissionManifest.check(s.manifest, s.files));
        }
    }

    @Test
    public void aFileChangedAfterPackingOrNotListedIsNamed() throws Exception {
        String manifest = sha256("sphere as packed") + "  " + SPHERE + "\n";
        Submission s = locate(submission("", Map.of(SPHERE, "sphere edited later", GROUP, "group", "MANIFEST.sha256", manifest)));
        assertEquals("MANIFEST.sha256: " + SPHERE + " is not the file gradle submission packed (its SHA-256 checksum differs:"
                + " changed after packing?); graded as handed in.\n"
                + "MANIFEST.sha256 does not list " + GROUP + ", so it was not checked against it.\n",
                SubmissionManifest.check(s.manifest, s.files));
    }

    /** sha256sum's binary-mode marker and upper-case hex are sha256sum's too; Windows line ends are harmless. */
    @Test
    public void sha256sumsOtherSpellingsAreRead() throws Exception {
        String manifest = sha256("sphere").toUpperCase() + " *" + SPHERE + "\r\n\r\n" + sha256("group") + "  " + GROUP + "\r\n";
        Submission s = locate(submission("", Map.of(SPHERE, "sphere", GROUP, "group", "MANIFEST.sha256", manifest)));
        assertTrue(SubmissionManifest.check(s.manifest, s.files), SubmissionManifest.check(s.manifest, s.files).contains("each of the 2"));
    }

    /** Whatever else a file of that name holds, the grader says it did not check, and quotes none of it. */
    @Test
    public void aManifestInAnotherFormIsNotCheckedAndNotQuoted() throws Exception {
        byte[] notText = {(byte) 0xff, (byte) 0xfe, (byte) 0xc3};
        for (byte[] content : List.of(("<b>not a checksum</b> " + SPHERE + "\n").getBytes(StandardCharsets.UTF_8), notText)) {
            Path root = submission("", Map.of(SPHERE, "sphere", GROUP, "group"));
            Files.write(root.resolve("MANIFEST.sha256"), content);
            Submission s = locate(root);
            String said = SubmissionManifest.check(s.manifest, s.files);
            assertTrue(said, said.startsWith("MANIFEST.sha256 ") && said.endsWith("the files were not checked against it.\n"));
            assertTrue(said, !said.contains("<b>") && !said.contains(root.toString()));
            assertEquals(said, 1, said.lines().count());
        }
    }

    @Test
    public void withoutAManifestThereIsNone() throws Exception {
        Submission s = locate(submission("", Map.of(SPHERE, "sphere", "notes.txt", "x")));
        assertNull(s.manifest);
        assertEquals(List.of("notes.txt"), s.ignored);
        assertEquals(List.of(GROUP), s.missing);
    }

    @Test
    public void theChecksumIsSha256sums() throws Exception {
        Path empty = folder.newFile().toPath();
        assertEquals("e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855", SubmissionManifest.sha256(empty));
    }
}
