package ray.image;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.math.Vec3;

/**
 * A process killed while it writes a PNG leaves the previous image whole: the new one is written to a
 * temporary file and renamed over the target. Killed with SIGTERM (what Ctrl-C and {@code kill} send),
 * the process also removes its temporary file; killed with SIGKILL it cannot, and the test checks it
 * was killed in the middle of a write by finding that file.
 */
public class PngWriterKillTest {
    /** Big enough that writing takes tens of milliseconds, so that most kills land inside a write. */
    private static final int SIDE = 2000;

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private Path target;

    @Test(timeout = 120_000)
    public void sigtermDuringAWriteLeavesAWholeImageAndNoTemporaryFile() throws Exception {
        target = folder.getRoot().toPath().resolve("scene.png");
        writeOriginal();
        Random random = new Random(7);
        for (int round = 0; round < 3; round++) {
            killDuringAWrite(false, random);
            assertWholeImage();
            assertEquals("the shutdown hook removed the temporary file", List.of("scene.png"), names());
        }
    }

    @Test(timeout = 120_000)
    public void sigkillDuringAWriteLeavesAWholeImage() throws Exception {
        target = folder.getRoot().toPath().resolve("scene.png");
        writeOriginal();
        Random random = new Random(11);
        int interrupted = 0;
        for (int round = 0; round < 4; round++) {
            killDuringAWrite(true, random);
            assertWholeImage();
            List<String> names = names();
            interrupted += names.size() > 1 ? 1 : 0;
            for (String name : names) {
                if (!name.equals("scene.png")) {
                    assertTrue(name, name.startsWith(".scene.png") && name.endsWith(".tmp"));
                    Files.delete(target.resolveSibling(name));
                }
            }
        }
        assertTrue("at least one kill landed inside a write (it left a temporary file)", interrupted > 0);
    }

    private void writeOriginal() throws Exception {
        Image image = new Image(8, 8);
        for (int j = 0; j < 8; j++) {
            for (int i = 0; i < 8; i++) {
                image.set(i, j, new Vec3(1, 0, 0));
            }
        }
        PngWriter.write(image, 1, target);
    }

    /** Starts the writing loop, lets it start a write after the first, and kills it a few milliseconds into it. */
    private void killDuringAWrite(boolean forcibly, Random random) throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), PngWriteLoop.class.getName(),
                target.toString(), Integer.toString(SIDE)).redirectErrorStream(true).start();
        BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        String line;
        while ((line = out.readLine()) != null && !line.equals("writing 2")) {
            // wait for the second write: the first may still be warming up the PNG encoder
        }
        Thread.sleep(random.nextInt(30));
        if (forcibly) {
            p.destroyForcibly();
        } else {
            p.destroy();
        }
        assertTrue(p.waitFor(30, TimeUnit.SECONDS));
    }

    /** The target decodes, and every pixel has one colour: the original red or one written grey, never a mix. */
    private void assertWholeImage() throws Exception {
        BufferedImage picture = PngReader.read(target);
        int first = picture.getRGB(0, 0);
        for (int y = 0; y < picture.getHeight(); y++) {
            for (int x = 0; x < picture.getWidth(); x++) {
                if (picture.getRGB(x, y) != first) {
                    throw new AssertionError("pixel " + x + "," + y + " differs from pixel 0,0: a partly written image");
                }
            }
        }
        int rgb = first & 0xffffff;
        boolean red = rgb == 0xff0000;
        boolean grey = (rgb >> 16) == (rgb & 0xff) && ((rgb >> 8) & 0xff) == (rgb & 0xff);
        assertTrue(Integer.toHexString(rgb), red || grey);
    }

    private List<String> names() throws Exception {
        try (Stream<Path> files = Files.list(target.getParent())) {
            return files.map(f -> f.getFileName().toString()).sorted().collect(Collectors.toList());
        }
    }
}
