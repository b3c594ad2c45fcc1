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

/** Task 4's scenes (see {@link RenderScenes#TASKS}), each rendered at full size and compared with its reference. */
@RunWith(Parameterized.class)
@Points(value = 2, task = StudentTask.GROUP)
public class GroupRenderTest extends RenderTestBase {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(StudentTask.GROUP).withTimeoutSeconds(TIMEOUT_SECONDS);

    public GroupRenderTest(String scene) {
        super(scene);
    }

    @Parameters(name = "{0}")
    public static List<Object[]> scenes() {
        return RenderScenes.scenesOf(StudentTask.GROUP);
    }

    @BeforeClass
    public static void clearReport() {
        RenderDiffReport.clear(GroupRenderTest.class);
    }

    @Override
    protected StudentTask task() {
        return StudentTask.GROUP;
    }
}
