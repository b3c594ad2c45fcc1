package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * {@code ray1 render} refuses to write into a folder of reference renders (one holding the
 * {@link RenderCommand#REFERENCE_MARKER} file), so a student's render never replaces the images
 * it is graded against. The refusal comes before any rendering, so it holds with stub code too.
 */
public class RenderReferenceGuardTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void renderRefusesAFolderWithTheReferenceMarkerAndWritesNothing() throws Exception {
        Path root = folder.getRoot().toPath();
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        Path reference = Files.createDirectories(root.resolve("reference"));
        Files.writeString(reference.resolve(RenderCommand.REFERENCE_MARKER), "marker\n");
        byte[] before = "not really a png".getBytes();
        Files.write(reference.resolve("floor.png"), before);

        CliRun run = CliRun.of("render", "-o", reference.toString(), scene.toString());

        assertEquals(run.toString(), 1, run.status);
        assertEquals(run.toString(), "error: " + reference + " holds the reference images (it has a .references file); "
                + "render somewhere else, e.g. -o out", run.err.strip());
        assertEquals(run.toString(), "", run.out);
        assertEquals("the existing image is untouched", new String(before), Files.readString(reference.resolve("floor.png")));
        run.assertNoStackTrace();
    }

    @Test
    public void aFolderWithoutTheMarkerIsNotRefused() throws Exception {
        Path root = folder.getRoot().toPath();
        Path scene = CliRun.write(root.resolve("floor.xml"), CliRun.floorScene(""));
        Path output = root.resolve("out");
        CliRun run = CliRun.of("render", "-o", output.toString(), scene.toString());
        assertFalse(run.toString(), run.err.contains("reference"));
        assertEquals(run.toString(), 0, run.status);
    }
}
