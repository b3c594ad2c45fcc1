package ray.accuracy;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.PngReader;

/** The report folder: an offline index.html whose every image exists, two SVG plots per scene and results.md. */
public class ReportWriterTest {
    @ClassRule
    public static TemporaryFolder folder = new TemporaryFolder();

    static Path report;
    static SceneStudy study;
    static String html;

    @BeforeClass
    public static void writeTheReport() throws Exception {
        Path root = folder.getRoot().toPath();
        study = new AccuracyStudy(List.of(1, 4), 8, null, 16, 3, 1, line -> { }).study(SmallScenes.load(root));
        report = root.resolve("report");
        ReportWriter.write(List.of(study), report, "ray1 accuracy test");
        html = new String(Files.readAllBytes(report.resolve("index.html")), StandardCharsets.UTF_8);
    }

    @Test
    public void everyRunHasARowAndItsWindowAndDifferenceImages() throws Exception {
        assertTrue(html.contains("<h2 id=\"sphere-on-floor\">sphere-on-floor</h2>"));
        assertTrue(html.contains("<code>ray1 accuracy test</code>"));
        for (Run run : study.runs) {
            String label = ReportWriter.escape(run.setting.label);
            assertTrue(label, html.contains("<td>" + label + "</td>"));
            String slug = ReportWriter.slug(run.setting.label);
            assertEquals(8, PngReader.read(report.resolve("sphere-on-floor/" + slug + ".png")).getWidth());
            assertEquals(8, PngReader.read(report.resolve("sphere-on-floor/" + slug + "-diff.png")).getWidth());
            assertEquals(slug, run.defectMap != null, Files.exists(report.resolve("sphere-on-floor/" + slug + "-defects.png")));
        }
    }

    @Test
    public void theReportOpensOfflineAndEveryFileItShowsExists() {
        assertFalse("no network", html.contains("http:") || html.contains("https:") || html.contains("<script"));
        Matcher src = Pattern.compile("src=\"([^\"]+)\"").matcher(html);
        int images = 0;
        while (src.find()) {
            images++;
            assertTrue(src.group(1), Files.isRegularFile(report.resolve(src.group(1).replace("&amp;", "&"))));
        }
        assertEquals("two plots, the reference, two per run and the defect maps", 3 + 2 * study.runs.size()
                + study.runs.stream().filter(r -> r.defectMap != null).count(), images);
    }

    @Test
    public void thePlotsAreWellFormedSvg() throws Exception {
        for (String plot : new String[] {"error-time.svg", "convergence.svg"}) {
            var svg = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(report.resolve("sphere-on-floor/" + plot).toFile());
            assertEquals("svg", svg.getDocumentElement().getNodeName());
        }
        String errorTime = new String(Files.readAllBytes(report.resolve("sphere-on-floor/error-time.svg")), StandardCharsets.UTF_8);
        assertTrue(errorTime.contains(">Pareto front<"));
        String convergence = new String(Files.readAllBytes(report.resolve("sphere-on-floor/convergence.svg")), StandardCharsets.UTF_8);
        assertTrue(convergence.contains(">ideal N^-0.5<"));
        assertTrue(convergence.contains(">jittered fit N^"));
    }

    @Test
    public void resultsMdHasTheTableAndTheReading() throws Exception {
        String md = new String(Files.readAllBytes(report.resolve("results.md")), StandardCharsets.UTF_8);
        assertTrue(md.startsWith("### sphere-on-floor\n"));
        assertTrue(md.contains("|sweep|setting|time (ms)|spread (ms)|runs|rays|RMSE|max error|PSNR (dB)|visibly off|defects|"));
        assertEquals(study.runs.size(), md.lines().filter(l -> l.matches("\\|(samples|arithmetic|intersection|offsets|acceleration)\\|.*")).count());
        assertTrue(md.contains(Reading.of(study).get(0)));
        try (Stream<Path> files = Files.walk(report)) {
            assertEquals("no temporary files left", 0, files.filter(p -> p.getFileName().toString().startsWith(".accuracy-")).count());
        }
    }

    @Test
    public void slugsAreFileNames() {
        assertEquals("jittered-16", ReportWriter.slug("jittered 16"));
        assertEquals("offset-fixed-1e-6", ReportWriter.slug("offset fixed 1e-6"));
        assertEquals("float-double-s-offsets", ReportWriter.slug("float, double's offsets"));
    }
}
