package ray.render;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertThrows;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.Test;
import ray.accuracy.Sweep;
import ray.accuracy.Sweeps;
import ray.image.Image;
import ray.scene.Scene;
import ray.scene.SceneLoader;
import ray.scene.SceneOptions;
import ray.shading.Course;

/**
 * Cutting paths of mirror rays after N hits ({@link RenderPlan#withPathHits}), what the accuracy
 * study's depth sweep measures: one hit traces no mirror ray, each further hit adds rays only where
 * the last one met a mirror, and 12 (the course's limit) is the render itself.
 */
public class PathHitsTest {
    private static final Scene CORRIDOR = SceneLoader.load(Path.of("scenes-2019/mirror-corridor.xml"), SceneOptions.of(Course.Y2019, null));

    private static RenderResult render(RenderPlan plan) {
        return new Renderer(plan, 2).render();
    }

    @Test
    public void oneHitTracesNoMirrorRayAndDeeperPathsTraceMore() {
        long last = -1;
        for (int hits = 1; hits <= 12; hits++) {
            RenderResult r = render(RenderPlan.of(CORRIDOR).withPathHits(hits));
            if (hits == 1) {
                assertEquals(0, r.rays.reflection);
            }
            assertTrue("depth " + hits + ": " + r.rays.reflection + " mirror rays after " + last, r.rays.reflection > last);
            last = r.rays.reflection;
        }
    }

    @Test
    public void twelveHitsIsTheCoursesLimitSoTheImageIsTheRendersOwn() {
        RenderResult own = render(RenderPlan.of(CORRIDOR));
        RenderResult twelve = render(RenderPlan.of(CORRIDOR).withPathHits(12));
        assertArrayEquals(pixels(own.image), pixels(twelve.image), 0);
        assertEquals(own.rays.reflection, twelve.rays.reflection);
        RenderResult eleven = render(RenderPlan.of(CORRIDOR).withPathHits(11));
        assertTrue("the corridor's mirrors see each other past 11 hits", own.rays.reflection > eleven.rays.reflection);
    }

    @Test
    public void thePlanSaysTheDepth() {
        assertTrue(RenderPlan.of(CORRIDOR).toString(), RenderPlan.of(CORRIDOR).toString().contains("reflection(1 shader, depth 12)"));
        assertTrue(RenderPlan.of(CORRIDOR).withPathHits(3).toString().contains("reflection(1 shader, depth 3)"));
        assertThrows(IllegalArgumentException.class, () -> RenderPlan.of(CORRIDOR).withPathHits(0));
    }

    @Test
    public void theDepthSweepRunsTwelveDownToOne() {
        Sweep depth = Sweeps.depth();
        assertEquals("depth 12", depth.baseline().label);
        assertEquals(12, depth.settings.size());
        assertTrue(depth.hasBaseline);
        assertEquals(List.of("samples", "arithmetic", "intersection", "fresnel", "masking", "offsets", "depth", "acceleration"), Sweeps.ALL);
    }

    private static double[] pixels(Image image) {
        double[] values = new double[image.width() * image.height() * 3];
        int k = 0;
        for (int j = 0; j < image.height(); j++) {
            for (int i = 0; i < image.width(); i++) {
                ray.math.Vec3 c = image.get(i, j);
                values[k++] = c.x;
                values[k++] = c.y;
                values[k++] = c.z;
            }
        }
        return values;
    }
}
