package ray.endtoend;

import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.ImageDiff;
import ray.testing.ProjectFolder;
import ray.testing.StudentTask;

/** The render-diff page: the commands it gives work as typed, and it tells "none ran" from "all matched". */
public class RenderDiffReportTest {
    @Rule
    public final TemporaryFolder temporary = new TemporaryFolder();

    private String page(RenderDiffReport report) throws Exception {
        return new String(Files.readAllBytes(report.index()), StandardCharsets.UTF_8);
    }

    @Test
    public void aPageWrittenBeforeAnyRenderSaysNoneRan() throws Exception {
        RenderDiffReport report = new RenderDiffReport(temporary.getRoot().toPath());
        report.clearEntries(SphereRenderTest.class);
        String html = page(report);
        assertTrue(html, html.contains("No render test has run yet"));
        assertFalse(html, html.contains("matches its reference"));
    }

    @Test
    public void matchingScenesAreCountedAsSuch() throws Exception {
        RenderDiffReport report = new RenderDiffReport(temporary.getRoot().toPath());
        report.clearEntries(SphereRenderTest.class);
        report.record(SphereRenderTest.class, "one-sphere", true);
        report.record(SphereRenderTest.class, "globe", true);
        assertTrue(page(report), page(report).contains("Every scene the last run rendered (2) matches its reference."));
    }

    @Test
    public void aSceneInASubfolderIsRenderedByItsRealPath() throws Exception {
        RenderDiffReport report = new RenderDiffReport(temporary.getRoot().toPath());
        BufferedImage black = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        BufferedImage white = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        for (int x = 0; x < 4; x++) {
            for (int y = 0; y < 4; y++) {
                white.setRGB(x, y, 0xffffff);
            }
        }
        report.record(SphereRenderTest.class, "one-sphere", true);
        report.record(SphereRenderTest.class, "far-tiny-sphere", false);
        // The test reads the scene by its absolute path; the page names it as typed in the project folder.
        String location = report.addEntry(SphereRenderTest.class, "far-tiny-sphere", ProjectFolder.resolve("scenes", "hard", "far-tiny-sphere.xml"),
                StudentTask.of("sphere"), ImageDiff.compare(white, black), black, white,
                "The scene uses Task 1 (Camera rays), Task 2 (Sphere) and Task 4 (Group).\nA second finding.", List.of());
        // The message links to the scene's own section of the page.
        assertTrue(location, location.endsWith("index.html#SphereRenderTest-far-tiny-sphere"));
        String html = page(report);
        assertTrue(html, html.contains("<section id=\"SphereRenderTest-far-tiny-sphere\">"));
        assertTrue(html, html.contains("<p>The scene uses Task 1 (Camera rays), Task 2 (Sphere) and Task 4 (Group).</p>\n<p>A second finding.</p>"));
        assertTrue(html, html.contains("Graded under Task 2 (Sphere) by <code>ray.endtoend.SphereRenderTest</code>"));
        assertTrue(html, html.contains("render -o out scenes/hard/far-tiny-sphere.xml\""));
        assertFalse(html, html.contains("scenes/far-tiny-sphere.xml"));
        assertTrue(html, html.contains("1 of 2 scenes rendered in the last run differ"));
        assertTrue(Files.isRegularFile(temporary.getRoot().toPath().resolve("SphereRenderTest/far-tiny-sphere-diff.png")));
    }

    /** A microfacet scene's entry shows each factor alone, the student's beside the reference's, and says which differs. */
    @Test
    public void aMicrofacetSceneShowsEachFactorAloneAndWhichDiffers() throws Exception {
        RenderDiffReport report = new RenderDiffReport(temporary.getRoot().toPath());
        BufferedImage black = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        BufferedImage white = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        for (int x = 0; x < 4; x++) {
            for (int y = 0; y < 4; y++) {
                white.setRGB(x, y, 0xffffff);
            }
        }
        List<MicrofacetFactorViews.View> factors = List.of(
                new MicrofacetFactorViews.View(ray.shading.MicrofacetFactor.D, black, white, ImageDiff.compare(white, black)),
                new MicrofacetFactorViews.View(ray.shading.MicrofacetFactor.F, white, white, ImageDiff.compare(white, white)),
                new MicrofacetFactorViews.View(ray.shading.MicrofacetFactor.G, white, white, ImageDiff.compare(white, white)));
        report.record(MicrofacetRenderTest.class, "microfacet-debug", false);
        report.addEntry(MicrofacetRenderTest.class, "microfacet-debug", ProjectFolder.resolve("scenes-2019", "microfacet-debug.xml"),
                StudentTask.of("microfacet"), ImageDiff.compare(white, black), black, white, MicrofacetFactorViews.line(factors), factors);
        String html = page(report);
        assertTrue(html, html.contains("<p>D alone <span class=\"fail\">(differs)</span>:</p>"));
        assertTrue(html, html.contains("<p>F alone (matches):</p>"));
        assertTrue(html, html.contains("MicrofacetRenderTest/microfacet-debug-D-yours.png"));
        assertTrue(html, html.contains("Each microfacet factor alone (ray1 render --microfacet-term D, F or G): D differs ("));
        assertTrue(Files.isRegularFile(temporary.getRoot().toPath().resolve("MicrofacetRenderTest/microfacet-debug-G-reference.png")));
    }
}
