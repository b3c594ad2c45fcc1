package ray.variants;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * A failed render test says, on the line after its summary, what the differing pixels show in the
 * student's render and where the worst one is, with the command that explains it: here for the
 * known-wrong sphere whose normals point inward, graded as the grader grades it.
 */
public class DifferingPixelsMessageTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private static final Pattern SUMMARY = Pattern.compile(
            "(scenes/\\S+\\.xml) does not look like \\S+: max \\d+, mean [\\d.]+, (\\d+) of \\d+ pixels \\([\\d.]+%\\) differ by more than 2 levels"
                    + " \\(allowed 0\\.2%\\)\\.\n    (\\d+) pixels differ; (\\d+) of them are on spheres \\(Task 2\\)(.*)\\.\n"
                    + "    The worst pixel is \\((\\d+), (\\d+)\\): see how your code lit it with `ray1 trace (\\S+) (\\d+) (\\d+)`"
                    + " \\(or explore it with `ray1 explore (\\S+)`\\)[.\n]");

    @Test
    public void aSphereWithInwardNormalsDiffersOnSpheresAndNamesItsWorstPixel() throws Exception {
        List<VariantGrading.Outcome> outcomes = VariantGrading.run(Variant.wrong("sphere-normal-inward", 2),
                (task, type) -> type.equals("ray.endtoend.SphereRenderTest"), folder.newFolder().toPath());
        int failed = 0;
        for (VariantGrading.Outcome o : outcomes) {
            if (o.passed()) {
                continue;
            }
            failed++;
            Matcher m = SUMMARY.matcher(o.failure);
            assertTrue(o.failure, m.find());
            assertEquals("the differing pixels counted twice", m.group(2), m.group(3));
            assertEquals("the scene named three times", m.group(1), m.group(8));
            assertEquals(m.group(1), m.group(11));
            assertEquals("the pixel and the command's", m.group(6) + " " + m.group(7), m.group(9) + " " + m.group(10));
            if (o.test.contains("[one-sphere]")) {
                // A lone sphere on the background: every pixel that differs is the sphere's.
                assertEquals(o.failure, m.group(3), m.group(4));
                assertEquals(o.failure, "", m.group(5));
            }
        }
        assertTrue(outcomes.toString(), failed >= 2);
    }
}
