package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * {@code --course} and {@code --scene-root} on the commands that load scenes: 2019's rules when
 * asked, a 2019 scene refused under 2017 in one line, and a bad value as a usage error naming it.
 */
public class CourseOptionTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private static final String SPHERE = "scenes-2019/one-sphere-lambertian.xml";
    private static final String MIRRORS = "scenes-2019/mirror-spheres.xml";

    @Test
    public void traceUnder2019SaysTheBrdfAndTheCentersValue() {
        CliRun run = CliRun.of("trace", "--course", "2019", SPHERE, "100", "100");
        assertEquals(run.toString(), 0, run.status);
        assertTrue(run.out, run.out.contains("Lambertian, kd = (0.8, 0.5, 0.2) (2019: f = ρd/π)"));
        assertTrue(run.out, run.out.contains("kd/π ⊙ I · max(0, n·l) / r² = (0.8, 0.5, 0.2)/π ⊙ (64, 64, 64) · 1 / 16"));
        // (0.8, 0.5, 0.2)·4/π = (1.01859, 0.63662, 0.254648), times exposure 0.5.
        assertTrue(run.out, run.out.contains("radiance     (1.01859, 0.63662, 0.254648)"));
    }

    @Test
    public void renderUnder2017RefusesAMirrorSceneInOneLineAndRendersItUnder2019() {
        Path out = folder.getRoot().toPath().resolve("out");
        CliRun y2017 = CliRun.of("render", "--course", "2017", "-o", out.toString(), MIRRORS);
        assertEquals(1, y2017.status);
        String[] errors = CliRun.lines(y2017.err);
        assertTrue(y2017.err, errors[0].startsWith("error: " + MIRRORS + ":37:26: <mirrorCoefficient> (lines 37 and 47) is in the"
                + " course's 2019 conventions only, and this scene loads by 2017's; render it with --course 2019"));
        assertFalse(out.resolve("mirror-spheres.png").toFile().exists());
        CliRun y2019 = CliRun.of("render", "--course", "2019", "-o", out.toString(), MIRRORS);
        assertEquals(y2019.toString(), 0, y2019.status);
        assertTrue(y2019.out, y2019.out.contains("reflection(2 shaders, depth 12)"));
        assertTrue(out.resolve("mirror-spheres.png").toFile().isFile());
        // Without --course, a scene under scenes-2019/ renders by its folder's conventions.
        Path byFolder = folder.getRoot().toPath().resolve("by-folder");
        CliRun shipped = CliRun.of("render", "-o", byFolder.toString(), MIRRORS);
        assertEquals(shipped.toString(), 0, shipped.status);
        assertTrue(byFolder.resolve("mirror-spheres.png").toFile().isFile());
    }

    @Test
    public void aCourseRayOneDoesNotKnowIsAUsageError() {
        CliRun run = CliRun.of("render", "--course", "2018", SPHERE);
        assertEquals(2, run.status);
        assertEquals("--course must be 2017 or 2019, got '2018'", CliRun.lines(run.err)[0]);
    }

    @Test
    public void aSceneRootThatIsNoFolderIsAUsageError() {
        CliRun run = CliRun.of("trace", "--scene-root", "no/such/folder", SPHERE, "1", "1");
        assertEquals(2, run.status);
        assertEquals("--scene-root no/such/folder is not a folder", CliRun.lines(run.err)[0]);
    }
}
