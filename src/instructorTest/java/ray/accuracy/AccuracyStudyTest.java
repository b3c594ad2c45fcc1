package ray.accuracy;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import ray.image.ImageError;
import ray.render.PixelWindow;
import ray.render.RenderPlan;
import ray.render.Renderer;
import ray.scene.Scene;

/**
 * The accuracy study of a small lit scene, every sweep run once for the class: what it measures
 * per setting, and that the measurements mean what the report says.
 */
public class AccuracyStudyTest {
    @ClassRule
    public static TemporaryFolder folder = new TemporaryFolder();

    static Scene scene;
    static SceneStudy study;
    static final List<String> log = new ArrayList<>();

    @BeforeClass
    public static void runTheStudy() throws Exception {
        scene = SmallScenes.load(folder.getRoot().toPath());
        study = new AccuracyStudy(List.of(1, 4, 16), 16, null, 256, 3, 1, log::add).study(scene);
    }

    @Test
    public void everySweepOfTheInstructorsCopyIsMeasured() {
        assertEquals(List.of(), study.missing);
        assertEquals(6, study.runs("samples").size());
        assertEquals(List.of("double", "float", "float, double's offsets"), labels(study.runs("arithmetic")));
        assertEquals(List.of("robust", "textbook"), labels(study.runs("intersection")));
        assertEquals(List.of("offset scaled", "offset error bound", "offset fixed 1e-6", "offset none"), labels(study.runs("offsets")));
        assertEquals("one log line per setting and one for the reference", study.runs.size() + 1, log.size());
    }

    @Test
    public void theWindowIsTheBusiestSixteenSquareOfTheImage() {
        Scene s = scene;
        PixelWindow expected = WindowChooser.busiest(new Renderer(RenderPlan.of(s), 1).render().image, s.getExposure(), 16);
        assertEquals(expected, study.window);
        assertEquals(16, study.reference.width());
    }

    @Test
    public void everyRunIsTimedAtLeastThreeTimesAndCountsItsRays() {
        for (Run run : study.runs) {
            assertTrue(run.setting.label, run.timing.runs >= 3);
            assertTrue(run.setting.label, run.timing.minSeconds <= run.timing.medianSeconds
                    && run.timing.medianSeconds <= run.timing.maxSeconds);
            int samples = run.setting.samples == 0 ? 1 : run.setting.samples;
            // One camera ray per sample, and at most one shadow ray per camera ray (one light, no mirrors).
            assertTrue(run.setting.label + ": " + run.rays, run.rays >= 256L * samples && run.rays <= 2 * 256L * samples);
        }
    }

    @Test
    public void aChoiceThatIsTheBaselineHasNoDefectsAndTheSameWindowAsOneGridSample() {
        Run grid = study.run("grid 1");
        for (String label : new String[] {"double", "robust", "offset scaled"}) {
            Run baseline = study.run(label);
            assertEquals(label, 0, baseline.defects, 0);
            assertEquals(label, null, baseline.defectMap);
            assertEquals(label + " renders what grid 1 does", 0, ImageError.of(baseline.window, grid.window, 1).maxError, 0);
        }
        assertTrue("the samples sweep has no baseline", Double.isNaN(grid.defects));
    }

    @Test
    public void noOffsetLeavesAcneOnTheLitSurfacesAndTheFrameworksRuleNone() {
        Run none = study.run("offset none");
        // Many lit pixels re-hit their own surface (11% of the image when written).
        assertTrue("defects " + none.defects, none.defects > 0.05);
        assertNotNull(none.defectMap);
        assertEquals(48, none.defectMap.getWidth());
        assertTrue(none.error.rmse > study.run("offset scaled").error.rmse);
        assertEquals("the error-bound offset leaves no acne with the solution's code", 0, study.run("offset error bound").defects, 0);
        assertEquals("float with double's offsets: acne too", true, study.run("float, double's offsets").defects > 0.05);
        assertTrue("float with float's offsets: " + study.run("float").defects, study.run("float").defects < 0.01);
    }

    @Test
    public void moreGridSamplesLowerTheErrorAgainstTheReference() {
        double previous = Double.POSITIVE_INFINITY;
        for (String label : new String[] {"grid 1", "grid 4", "grid 16"}) {
            double rmse = study.run(label).error.rmse;
            assertTrue(label + ": " + rmse + " after " + previous, rmse < previous);
            previous = rmse;
        }
        assertTrue(study.run("jittered 16").error.rmse < study.run("jittered 1").error.rmse);
        assertTrue("16 samples take longer than 1", study.run("grid 16").seconds() > study.run("grid 1").seconds());
    }

    @Test
    public void theReadingNamesTheFrontAndEveryChoiceSweep() {
        List<String> reading = Reading.of(study);
        assertTrue(reading.get(0), reading.get(0).startsWith("Samples per pixel: grid RMSE falls as N^-"));
        assertTrue(reading.get(1), reading.get(1).startsWith("Samples worth their time"));
        assertTrue(reading.get(2), reading.get(2).startsWith("Arithmetic (against double): float takes"));
        assertTrue(reading.get(4), reading.get(4).contains("offset none takes")
                && reading.get(4).contains("(shadow acne: rays that hit their own surface)"));
        // The floor scene has no mesh: the acceleration sweep changes nothing, in the image or (much) the time.
        assertTrue(reading.get(5), reading.get(5).startsWith("Acceleration (against bvh): linear takes")
                && reading.get(5).endsWith("The same image either way: acceleration is time saved at no cost in accuracy."));
        assertEquals(6, reading.size());
    }

    private static List<String> labels(List<Run> runs) {
        List<String> labels = new ArrayList<>();
        runs.forEach(r -> labels.add(r.setting.label));
        return labels;
    }
}
