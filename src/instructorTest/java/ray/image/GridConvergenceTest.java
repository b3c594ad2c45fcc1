package ray.image;

import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneLoader;

/**
 * On a scene whose image is smooth (a lit floor filling the view: no edges, no shadows), the
 * regular grid is the midpoint rule over each pixel, whose error falls as 1/n² for n×n samples:
 * more samples never raise the error against a 64×64-sample render. This checks the measurement
 * (ImageError) and the sampler together; it needs the solution's camera and triangle.
 */
public class GridConvergenceTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private static final String SMOOTH_FLOOR = "<?xml version=\"1.0\"?>\n<scene>\n"
            + "  <camera type=\"PerspectiveCamera\"><viewPoint>0 1.5 3</viewPoint><viewDir>0 -1.5 -3</viewDir>"
            + "<projDistance>2</projDistance></camera>\n"
            + "  <image>16 12</image>\n"
            + "  <light><position>0.7 0.8 0.4</position><intensity>1 1 1</intensity></light>\n"
            + "  <surface type=\"Triangle\"><shader type=\"Lambertian\"><diffuseColor>0.8 0.8 0.8</diffuseColor></shader>"
            + "<v0>-100 0 -100</v0><v1>-100 0 100</v1><v2>100 0 0</v2></surface>\n"
            + "</scene>\n";

    @Test
    public void moreGridSamplesNeverRaiseTheErrorOnASmoothImage() throws Exception {
        Path file = folder.getRoot().toPath().resolve("smooth-floor.xml");
        Files.write(file, SMOOTH_FLOOR.getBytes(StandardCharsets.UTF_8));
        Scene scene = SceneLoader.load(file);
        Image reference = new Renderer(scene, 64 * 64, 0).render().image;
        double previous = Double.POSITIVE_INFINITY;
        StringBuilder errors = new StringBuilder();
        for (int samples : new int[] {1, 4, 16, 64, 256}) {
            double rmse = ImageError.of(new Renderer(scene, samples, 0).render().image, reference, 1).rmse;
            errors.append(samples).append(": ").append(rmse).append("; ");
            assertTrue("RMSE by samples per pixel: " + errors, rmse < previous);
            previous = rmse;
        }
        // The midpoint rule's 1/n² rate: from 16 to 256 samples (n = 4 to 16), at least 10× smaller.
        double at16 = ImageError.of(new Renderer(scene, 16, 0).render().image, reference, 1).rmse;
        assertTrue("RMSE by samples per pixel: " + errors, previous < at16 / 10);
    }
}
