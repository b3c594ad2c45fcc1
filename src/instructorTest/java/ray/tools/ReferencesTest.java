package ray.tools;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.cli.RenderCommand;
import ray.image.PngReader;

/**
 * {@link References} on a small scenes folder: one full-size PNG per scene (subfolders included,
 * the reference folder itself skipped), the README and the marker written, stale PNGs removed,
 * and two scenes with one name refused.
 */
public class ReferencesTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    /**
     * A 3×2 orthographic view of [−1.5, 1.5] × [−1, 1] at z = 0, all covered by a white Lambertian
     * triangle lit by a light of intensity 1 at distance 1 straight above the middle.
     */
    private static String scene(String light) {
        return "<scene>\n"
                + "  <camera type=\"OrthographicCamera\"><viewPoint>0 0 5</viewPoint>"
                + "<viewWidth>3</viewWidth><viewHeight>2</viewHeight></camera>\n"
                + "  <image>3 2</image>\n"
                + "  <light><position>0 0 1</position><intensity>" + light + "</intensity></light>\n"
                + "  <surface type=\"Triangle\"><v0>-40 -40 0</v0><v1>40 -40 0</v1><v2>0 40 0</v2></surface>\n"
                + "</scene>\n";
    }

    @Test
    public void rendersEverySceneAtFullSizeAndWritesReadmeAndMarker() throws Exception {
        Path scenes = folder.getRoot().toPath();
        Files.writeString(scenes.resolve("a.xml"), scene("1 1 1"));
        Files.createDirectories(scenes.resolve("more"));
        Files.writeString(scenes.resolve("more/b.xml"), scene("0 0 0"));
        Path reference = Files.createDirectories(scenes.resolve("reference"));
        // A scene file inside the reference folder is not a scene to render.
        Files.writeString(reference.resolve("ignored.xml"), scene("1 1 1"));
        Files.writeString(reference.resolve("stale.png"), "old");

        assertEquals(0, References.run(scenes));

        BufferedImage a = PngReader.read(reference.resolve("a.png"));
        assertEquals(3, a.getWidth());
        assertEquals(2, a.getHeight());
        // Pixel (1, 0) looks at (0, −0.5, 0): r² = 0.25 + 1 = 1.25, n·l = 1/√1.25, L = 1/1.25^1.5 = 0.71554,
        // floor(255·0.71554^(1/2.2) + ½) = floor(255·0.85899 + ½) = 219.
        assertEquals(0xdbdbdb, a.getRGB(1, 1) & 0xffffff);
        assertEquals(0, PngReader.read(reference.resolve("b.png")).getRGB(1, 1) & 0xffffff);
        assertFalse("stale PNG removed", Files.exists(reference.resolve("stale.png")));
        assertFalse("nothing rendered from the reference folder", Files.exists(reference.resolve("ignored.png")));
        assertTrue(Files.exists(reference.resolve(RenderCommand.REFERENCE_MARKER)));
        assertTrue(Files.readString(reference.resolve("README.md")).contains("gradle references"));
    }

    @Test
    public void aScenesWarningGoesToStderrAndItsReferenceIsStillRendered() throws Exception {
        Path scenes = folder.getRoot().toPath();
        Path file = scenes.resolve("a.xml");
        // A box given with minPt.y above maxPt.y, below the triangle and out of the light (line 6).
        Files.writeString(file, scene("1 1 1").replace("</scene>", "  <surface type=\"Box\">\n"
                + "    <minPt>5 5 -3</minPt><maxPt>6 4 -2</maxPt>\n  </surface>\n</scene>"));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream original = System.err;
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            assertEquals(0, References.run(scenes));
        } finally {
            System.setErr(original);
        }
        assertEquals(file + ":6:23: warning: Box minPt.y > maxPt.y; built from the corners as given, as the course's renderer does"
                + System.lineSeparator(), err.toString(StandardCharsets.UTF_8));
        assertEquals(0xdbdbdb, PngReader.read(scenes.resolve("reference/a.png")).getRGB(1, 1) & 0xffffff);
    }

    @Test
    public void twoScenesWithOneNameAreRefusedBeforeRendering() throws Exception {
        Path scenes = folder.getRoot().toPath();
        Files.writeString(scenes.resolve("a.xml"), scene("1 1 1"));
        Files.createDirectories(scenes.resolve("more"));
        Files.writeString(scenes.resolve("more/a.xml"), scene("1 1 1"));
        assertEquals(1, References.run(scenes));
        assertFalse(Files.exists(scenes.resolve("reference/a.png")));
    }
}
