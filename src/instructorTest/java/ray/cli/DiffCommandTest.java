package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.ImageDiff;
import ray.image.PngReader;
import ray.image.PngWriter;

/**
 * {@code ray1 diff A.png B.png [-o DIFF.png]}: the figures and PASS/FAIL it prints, the heat map it
 * writes, and its exit status: 0 pass, 1 fail (different sizes too), 2 when it cannot compare.
 */
public class DiffCommandTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Path root;

    @Before
    public void setUp() {
        root = folder.getRoot().toPath();
    }

    /** A w×h gray image (level 100) with pixel (x, y) set to {@code rgb}; x = −1 for none. */
    private Path png(String name, int w, int h, int x, int y, int rgb) throws Exception {
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                image.setRGB(i, j, 0x646464);
            }
        }
        if (x >= 0) {
            image.setRGB(x, y, rgb);
        }
        Path file = root.resolve(name);
        PngWriter.write(image, file);
        return file;
    }

    @Test
    public void equalImagesPassWithExitZeroAndABlackHeatMap() throws Exception {
        Path a = png("a.png", 10, 10, -1, 0, 0);
        Path b = png("b.png", 10, 10, -1, 0, 0);
        Path map = root.resolve("maps/diff.png");
        CliRun run = CliRun.of("diff", a.toString(), b.toString(), "-o", map.toString());
        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), "", run.err);
        String[] lines = CliRun.lines(run.out);
        assertEquals(run.toString(), "PASS: max 0, mean 0.000, 0 of 100 pixels (0.000%) differ by more than "
                + ImageDiff.TOLERANCE_LEVELS + " levels (allowed 0.2%)", lines[0]);
        assertEquals(run.toString(), "heat map: " + map, lines[1]);
        BufferedImage heat = PngReader.read(map);
        assertEquals(10, heat.getWidth());
        assertEquals(0, heat.getRGB(5, 5) & 0xffffff);
    }

    /** One pixel of 100 off by 100 levels in red: 1% differs, more than 0.2%, so FAIL and exit 1. */
    @Test
    public void aDifferenceBeyondTheAllowedShareFailsWithExitOneAndShowsInTheHeatMap() throws Exception {
        Path a = png("a.png", 10, 10, -1, 0, 0);
        Path b = png("b.png", 10, 10, 3, 4, 0xc86464);
        Path map = root.resolve("diff.png");
        CliRun run = CliRun.of("diff", a.toString(), b.toString(), "-o", map.toString());
        assertEquals(run.toString(), 1, run.status);
        // mean = 100 / (3·100) = 0.333
        assertTrue(run.toString(), run.out.startsWith("FAIL: max 100, mean 0.333, 1 of 100 pixels (1.000%) differ"));
        BufferedImage heat = PngReader.read(map);
        assertTrue("the differing pixel is colored", (heat.getRGB(3, 4) & 0xffffff) != 0);
        assertEquals(0, heat.getRGB(4, 3) & 0xffffff);
    }

    @Test
    public void withoutOutputOptionNoHeatMapIsWritten() throws Exception {
        Path a = png("a.png", 10, 10, -1, 0, 0);
        Path b = png("b.png", 10, 10, 0, 0, 0x656464);
        CliRun run = CliRun.of("diff", a.toString(), b.toString());
        assertEquals(run.toString(), 0, run.status);
        assertEquals(run.toString(), 1, CliRun.lines(run.out).length);
        try (var files = Files.list(root)) {
            assertEquals(2, files.count());
        }
    }

    @Test
    public void differentSizesAreOneFailLineWithExitOne() throws Exception {
        Path a = png("a.png", 10, 10, -1, 0, 0);
        Path b = png("b.png", 12, 10, -1, 0, 0);
        CliRun run = CliRun.of("diff", a.toString(), b.toString(), "-o", root.resolve("d.png").toString());
        assertEquals(run.toString(), 1, run.status);
        assertEquals(run.toString(), "FAIL: the images differ in size: " + a + " is 10x10, " + b + " is 12x10 (no heat map written)",
                run.out.strip());
        assertFalse(Files.exists(root.resolve("d.png")));
        run.assertNoStackTrace();
    }

    @Test
    public void aMissingFileIsOneErrorLineWithExitTwo() throws Exception {
        Path a = png("a.png", 10, 10, -1, 0, 0);
        Path missing = root.resolve("nope.png");
        CliRun run = CliRun.of("diff", a.toString(), missing.toString());
        assertEquals(run.toString(), 2, run.status);
        assertEquals(run.toString(), "error: " + missing + ": no such file", run.err.strip());
        assertEquals(run.toString(), "", run.out);
    }

    @Test
    public void aFileThatIsNotAPngIsOneErrorLineWithExitTwo() throws Exception {
        Path a = png("a.png", 10, 10, -1, 0, 0);
        Path text = Files.writeString(root.resolve("scene.png"), "<scene/>\n");
        CliRun run = CliRun.of("diff", text.toString(), a.toString());
        assertEquals(run.toString(), 2, run.status);
        assertEquals(run.toString(), "error: " + text + " is not a PNG file", run.err.strip());
    }

    @Test
    public void aTruncatedPngIsOneErrorLineWithExitTwo() throws Exception {
        Path a = png("a.png", 10, 10, -1, 0, 0);
        byte[] bytes = Files.readAllBytes(a);
        Path broken = Files.write(root.resolve("broken.png"), java.util.Arrays.copyOf(bytes, 20));
        CliRun run = CliRun.of("diff", a.toString(), broken.toString());
        assertEquals(run.toString(), 2, run.status);
        assertTrue(run.toString(), run.err.startsWith("error: " + broken + " is a damaged PNG file"));
        assertEquals(run.toString(), 1, CliRun.lines(run.err).length);
        run.assertNoStackTrace();
    }
}
