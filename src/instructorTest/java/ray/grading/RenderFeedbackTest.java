package ray.grading;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;

import java.awt.image.BufferedImage;
import org.junit.Test;

/** The worst pixel of a failed render, which the feedback's trace command explains. */
public class RenderFeedbackTest {
    @Test
    public void theWorstPixelIsWhereAnyChannelDiffersMostCountedFromTheTop() {
        BufferedImage a = new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB);
        BufferedImage b = new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB);
        b.setRGB(1, 0, 0x000010);
        b.setRGB(3, 2, 0x300000);
        b.setRGB(2, 1, 0x002f00);
        assertArrayEquals(new int[] {3, 2}, RenderFeedback.worstPixel(a, b));
        assertNull(RenderFeedback.worstPixel(a, new BufferedImage(3, 3, BufferedImage.TYPE_INT_RGB)));
    }

    @Test
    public void textIsEscapedForHtml() {
        assertEquals("a &lt;b&gt; &amp; &quot;c&quot;", RenderFeedback.escape("a <b> & \"c\""));
    }

    /** The render test's pointer to its report is a file on the grading machine: no platform shows it. */
    @Test
    public void theReportLineIsLeftOutOfEveryMessage() {
        String message = "[Task 2 (Sphere)] scenes/one-sphere.xml does not look like scenes/reference/one-sphere.png: max 9\n"
                + "    See your image, the reference and where they differ in file:///tmp/work-1/instructor/build/reports/render-diff/index.html\n"
                + "    Work on the TODO(Task 2) comments in src/main/java/ray/surface/Sphere.java.";
        assertEquals("[Task 2 (Sphere)] scenes/one-sphere.xml does not look like scenes/reference/one-sphere.png: max 9\n"
                + "    Work on the TODO(Task 2) comments in src/main/java/ray/surface/Sphere.java.", RenderFeedback.withoutReportLine(message));
        assertEquals("expected:<1> but was:<2>", RenderFeedback.withoutReportLine("expected:<1> but was:<2>"));
    }
}
