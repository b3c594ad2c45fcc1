package ray.render;

import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.Image;
import ray.image.ImageDiff;
import ray.image.PngWriter;
import ray.math.Vec3;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;
import ray.shading.Course;

/**
 * The 2019 shading's hard cases at the scale of whole renders: a mirror scene moved far from the
 * origin renders as it does at home (no acne from its mirror or shadow rays), and no 2019 scene has
 * a NaN, an infinity or a negative value in any pixel, grazing mirror rays at the silhouettes and
 * the corridor's 12-hit chains included.
 */
public class Course2019HardCasesTest {
    @Rule
    public final TemporaryFolder folder = new TemporaryFolder();

    private static final Pattern POINT = Pattern.compile("<(viewPoint|position|minPt|maxPt|center)>\\s*(\\S+)\\s+(\\S+)\\s+(\\S+)\\s*</");

    /** The scene text with every point (camera, lights, boxes, spheres) moved by {@code offset} on each axis. */
    private static String moved(String xml, double offset) {
        Matcher m = POINT.matcher(xml);
        StringBuilder out = new StringBuilder();
        while (m.find()) {
            String point = (Double.parseDouble(m.group(2)) + offset) + " " + (Double.parseDouble(m.group(3)) + offset) + " "
                    + (Double.parseDouble(m.group(4)) + offset);
            m.appendReplacement(out, "<" + m.group(1) + ">" + point + "</");
        }
        m.appendTail(out);
        return out.toString();
    }

    private static Image render(Path file) {
        Scene scene = SceneLoader.load(file, SceneOptions.of(Course.Y2019, null));
        return new Renderer(scene, 0, 0).render().image;
    }

    @Test
    public void mirrorScenesFarFromTheOriginRenderAsAtHome() throws IOException {
        for (String name : new String[] {"mirror-spheres", "mirror-corridor"}) {
            Path home = Path.of("scenes-2019", name + ".xml");
            String xml = Files.readString(home, StandardCharsets.UTF_8);
            for (double offset : new double[] {1e6, 1e9}) {
                Path far = folder.getRoot().toPath().resolve(name + "-" + (long) offset + ".xml");
                Files.writeString(far, moved(xml, offset), StandardCharsets.UTF_8);
                ImageDiff.Result diff = ImageDiff.compare(PngWriter.toBufferedImage(render(home), 1),
                        PngWriter.toBufferedImage(render(far), 1));
                assertTrue(name + " moved by " + offset + ": " + diff, diff.passed());
            }
        }
    }

    @Test
    public void everyPixelOfEvery2019SceneIsFiniteAndNotNegative() {
        for (Path file : SceneFiles.under(Path.of("scenes-2019"), Path.of("scenes-2019/reference"))) {
            Image image = render(file);
            for (int j = 0; j < image.height(); j++) {
                for (int i = 0; i < image.width(); i++) {
                    Vec3 c = image.get(i, j);
                    assertTrue(file + " pixel (" + i + ", " + j + ") = " + c, c.isFinite() && c.x >= 0 && c.y >= 0 && c.z >= 0);
                }
            }
        }
    }
}
