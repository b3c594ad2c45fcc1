package ray.accel;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.PngWriter;
import ray.render.RenderPlan;
import ray.render.RenderResult;
import ray.render.Renderer;
import ray.scene.Scene;
import ray.scene.SceneFiles;
import ray.scene.SceneLoader;

/**
 * Same image, proven: every shipped scene rendered at its own size and samples with acceleration and
 * without gives byte-identical PNG files. Acceleration changes which triangles a ray is tested
 * against, in which order, and whether a shadow ray looks for any blocker or the closest; none of
 * that may change a pixel. The students' tree (the solution's, here) gives the same bytes too.
 */
public class AccelerationIdentityTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void everyShippedSceneRendersToTheSameBytesWithAndWithoutAcceleration() throws IOException {
        List<Path> scenes = SceneFiles.under(Path.of("scenes"));
        assertEquals("every shipped scene", 25, scenes.size());
        int accelerated = 0;
        for (Path file : scenes) {
            String name = SceneFiles.nameOf(file);
            Scene scene = SceneLoader.load(file);
            RenderPlan plan = RenderPlan.of(scene);
            byte[] fast = png(new Renderer(plan, 2).render(), scene, name + "-bvh");
            RenderResult linear = new Renderer(plan.withAcceleration(Acceleration.NONE), 2).render();
            byte[] slow = png(linear, scene, name + "-none");
            assertArrayEquals(name + ": --accel bvh and --accel none differ", slow, fast);
            byte[] students = png(new Renderer(plan.withAcceleration(Acceleration.STUDENT), 2).render(), scene, name + "-student");
            assertArrayEquals(name + ": --accel student (the solution's tree) and --accel bvh differ", fast, students);
            accelerated += plan.runs(ray.shading.Effect.ACCELERATION) ? 1 : 0;
        }
        assertTrue("most shipped scenes have a mesh or box to accelerate: " + accelerated, accelerated >= 10);
    }

    private byte[] png(RenderResult result, Scene scene, String name) throws IOException {
        Path file = folder.getRoot().toPath().resolve(name + ".png");
        PngWriter.write(result.image, scene.getExposure(), file);
        return Files.readAllBytes(file);
    }
}
