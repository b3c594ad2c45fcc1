package ray.endtoend;

import java.util.List;
import org.junit.BeforeClass;
import org.junit.Rule;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import ray.testing.Points;
import ray.testing.StudentTask;
import ray.testing.StudentTaskRule;

/** Task 6's (extra credit) scenes (see {@link RenderScenes#TASKS}), each rendered at full size and compared with its reference. */
@RunWith(Parameterized.class)
@Points(value = 2, task = StudentTask.CYLINDER, bonus = true)
public class CylinderRenderBonusTest extends RenderTestBase {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.CYLINDER).withTimeoutSeconds(TIMEOUT_SECONDS);

    public CylinderRenderBonusTest(String scene) {
        super(scene);
    }

    @Parameters(name = "{0}")
    public static List<Object[]> scenes() {
        return RenderScenes.scenesOf(StudentTask.CYLINDER);
    }

    @BeforeClass
    public static void clearReport() {
        RenderDiffReport.clear(CylinderRenderBonusTest.class);
    }

    @Override
    protected StudentTask task() {
        return StudentTask.CYLINDER;
    }
}
