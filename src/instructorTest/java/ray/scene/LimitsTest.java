package ray.scene;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Input past the {@link Limits} gets a located one-line error before any memory is spent on it,
 * and input right at a limit is still accepted.
 */
public class LimitsTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Path scene(String image, String body) {
        return SceneFixtures.write(folder, "big.xml", "<scene>\n  <camera type=\"PerspectiveCamera\"/>\n  <image>" + image
                + "</image>\n" + body + "</scene>\n");
    }

    private static void assertMessage(String expected, Path file) {
        assertEquals(expected, SceneFixtures.loadError(file).getMessage());
    }

    @Test
    public void imageSideBeyondTheLimitIsRefusedAtTheImageElement() {
        Path file = scene("8193 10", "");
        assertMessage(file + ":3:10: image size 8193 10 is too large; expected each side at most 8192", file);
    }

    @Test
    public void imageWithTooManyPixelsIsRefused() {
        Path file = scene("8192 4096", "");
        assertMessage(file + ":3:10: image size 8192 4096 has 33554432 pixels; expected at most 16777216"
                + " (e.g. 4096 4096)", file);
    }

    @Test
    public void imagesAtTheLimitsLoad() {
        assertEquals(4096, SceneLoader.load(scene("4096 4096", "")).getWidth());
        assertEquals(8192, SceneLoader.load(scene("8192 2048", "")).getWidth());
    }

    @Test
    public void samplesBeyondTheLimitAreRefused() {
        Path file = scene("4 3", "  <samples>65537</samples>\n");
        assertMessage(file + ":4:12: samples is 65537; expected at most 65536 per pixel", file);
        assertEquals(65536, SceneLoader.load(scene("4 3", "  <samples>65536</samples>\n")).getSamples());
    }

    @Test
    public void sceneFileBeyondTheSizeLimitIsRefusedBeforeItIsRead() throws IOException {
        Path file = folder.getRoot().toPath().resolve("huge.xml");
        Files.write(file, new byte[(int) Limits.MAX_SCENE_BYTES + 1]);
        assertMessage(file + ":1:1: the file has 16777217 bytes; expected a scene file of at most 16777216 bytes", file);
    }

    /** {@code <scene>} and then groups nested inside each other, {@code levels} elements deep in all. */
    private Path nested(int levels) {
        StringBuilder xml = new StringBuilder("<scene>\n  <camera type=\"PerspectiveCamera\"/>\n  <image>4 3</image>\n");
        for (int i = 1; i < levels; i++) {
            xml.append("<surface type=\"Group\">\n");
        }
        for (int i = 1; i < levels; i++) {
            xml.append("</surface>\n");
        }
        return SceneFixtures.write(folder, "deep.xml", xml.append("</scene>\n").toString());
    }

    @Test
    public void nestingBeyondTheLimitIsRefusedAtTheElementThatPassesIt() {
        Path file = nested(65);
        // Line 4 holds the second level; the 65th level, the 64th group, is on line 3 + 64.
        assertMessage(file + ":67:23: elements are nested more than 64 deep; expected a scene of at most 64 levels", file);
        assertEquals(1, SceneLoader.load(nested(64)).getSurfaces().children().size());
    }

    @Test
    public void objLineBeyondTheLimitIsRefusedWithItsLineNumber() {
        Path obj = SceneFixtures.write(folder, "long.obj", "v 0 0 0\n#" + "x".repeat(Limits.MAX_OBJ_LINE) + "\n");
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.read(obj));
        assertEquals(obj + ":2:1: the line is longer than 65536 characters; expected an OBJ statement (v, vn, vt, f, ...)"
                + " per line", e.getMessage());
        Path atLimit = SceneFixtures.write(folder, "ok.obj", "v 0 0 0\r\n#" + "x".repeat(Limits.MAX_OBJ_LINE - 1)
                + "\r\nv 1 0 0\rv 0 1 0\nf 1 2 3");
        assertEquals(1, ObjReader.read(atLimit).triangleCount());
    }

    @Test
    public void meshCountsBeyondTheLimitsAreRefusedAtTheLineThatPassesThem() {
        Path obj = SceneFixtures.write(folder, "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1 2 3 4\n");
        SceneException vertices = assertThrows(SceneException.class, () -> ObjReader.read(obj, 3, 10));
        assertEquals(obj + ":4:1: the mesh has more than 3 vertices; expected at most 3", vertices.getMessage());
        SceneException triangles = assertThrows(SceneException.class, () -> ObjReader.read(obj, 4, 1));
        assertEquals(obj + ":6:1: the mesh has more than 1 triangles; expected at most 1", triangles.getMessage());
        assertEquals(2, ObjReader.read(obj, 4, 2).triangleCount());
    }
}
