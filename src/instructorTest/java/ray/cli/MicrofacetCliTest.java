package ray.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The microfacet shaders on the command line: {@code ray1 trace} shows a light's F, D, G1(l), G1(v)
 * and the facets' share as the shader's classes compute them, and agrees with the shader;
 * {@code --microfacet-term} renders one factor alone, and a bad value is a usage error naming it.
 */
public class MicrofacetCliTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    private static final String DEBUG = "scenes-2019/microfacet-debug.xml";

    @Test
    public void traceShowsEachFactorOfTheLight() {
        CliRun run = CliRun.of("trace", DEBUG, "120", "80");
        assertEquals(run.toString(), 0, run.status);
        assertTrue(run.out, run.out.contains("Microfacet, kd = (0, 0, 0) (2019: f = ρd/π + k_mf·F·D·G1(l)·G1(v) / (4|n·l||n·v|),"
                + " Beckmann α = 0.7, nt = 2, k_mf = (0.2, 0.3, 0.8))"));
        for (String row : new String[] {"h   ", "F   ", "D   ", "G1(l)", "G1(v)", "facets"}) {
            assertTrue(row + " missing:\n" + run.out, run.out.contains("\n      " + row));
        }
        assertTrue(run.out, run.out.contains("(Fresnel.reflectance(|l·h| = "));
        assertTrue(run.out, run.out.contains("(BeckmannDistribution.normalDistribution(n, h), α = 0.7)"));
        assertFalse(run.out, run.out.contains("✗"));
    }

    @Test
    public void eachFactorRendersAlone() {
        Path out = folder.getRoot().toPath().resolve("out");
        for (String term : new String[] {"D", "F", "G"}) {
            Path dir = out.resolve(term);
            CliRun run = CliRun.of("render", "--microfacet-term", term, "-o", dir.toString(), DEBUG);
            assertEquals(run.toString(), 0, run.status);
            assertTrue(dir.resolve("microfacet-debug.png").toFile().isFile());
        }
    }

    @Test
    public void aFactorThatIsNoneIsAUsageError() {
        CliRun run = CliRun.of("render", "--microfacet-term", "X", DEBUG);
        assertEquals(2, run.status);
        assertEquals("--microfacet-term must be D, F or G, got 'X'", CliRun.lines(run.err)[0]);
    }

    @Test
    public void aSceneWithoutMicrofacetShadersRefusesAFactorView() {
        CliRun run = CliRun.of("render", "--microfacet-term", "D", "-o", folder.getRoot().toString(), "scenes-2019/one-sphere-lambertian.xml");
        assertEquals(1, run.status);
        assertTrue(run.err, CliRun.lines(run.err)[0].endsWith("a view of the microfacet factor D was asked for, and this scene has no"
                + " microfacet shader (MicrofacetBeckmann, MicrofacetGGX or Microfacet)"));
    }
}
