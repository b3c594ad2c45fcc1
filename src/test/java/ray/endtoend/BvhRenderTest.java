package ray.endtoend;

import java.util.List;
import org.junit.BeforeClass;
import org.junit.Rule;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import ray.accel.Acceleration;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * The bvh task's scenes (its {@code scenes} in the table of tasks), each rendered at full size through
 * your tree (every mesh and box: your boxes, your build, your closestHit for camera rays and anyHit for
 * shadow rays) and compared with its reference. Every other render test of an assignment with this task
 * searches through your tree too.
 */
@RunWith(Parameterized.class)
@Points(2)
public class BvhRenderTest extends RenderTestBase {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass()).withTimeoutSeconds(FORWARDED_SEARCHES_TIMEOUT_SECONDS);

    public BvhRenderTest(String scene) {
        super(scene);
    }

    /** Your tree, whether or not the assignment has you write it (the instructor's tree renders the solution's). */
    @Override
    protected Acceleration acceleration() {
        return Acceleration.STUDENT;
    }

    @Parameters(name = "{0}")
    public static List<Object[]> scenes() {
        return RenderScenes.scenesOf(BvhRenderTest.class);
    }

    @BeforeClass
    public static void clearReport() {
        RenderDiffReport.clear(BvhRenderTest.class);
    }
}
