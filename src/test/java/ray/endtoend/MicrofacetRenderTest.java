package ray.endtoend;

import java.util.List;
import org.junit.BeforeClass;
import org.junit.Rule;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/** The microfacet task's scenes (its {@code scenes} in the table of tasks, under scenes-2019/), each rendered by the 2019 conventions at full size and compared with its reference. */
@RunWith(Parameterized.class)
@Points(2)
public class MicrofacetRenderTest extends RenderTestBase {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass()).withTimeoutSeconds(TIMEOUT_SECONDS);

    public MicrofacetRenderTest(String scene) {
        super(scene);
    }

    @Parameters(name = "{0}")
    public static List<Object[]> scenes() {
        return RenderScenes.scenesOf(MicrofacetRenderTest.class);
    }

    @BeforeClass
    public static void clearReport() {
        RenderDiffReport.clear(MicrofacetRenderTest.class);
    }
}
