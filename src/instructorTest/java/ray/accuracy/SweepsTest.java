package ray.accuracy;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import ray.render.RayOffsets;
import ray.render.SamplePattern;

/** The study's sweeps: what each setting renders with, and which sweeps a copy lacks. */
public class SweepsTest {
    @Test
    public void theSamplesSweepHasGridThenJitteredAtEachCount() {
        Sweep sweep = Sweeps.samples(List.of(1, 4, 16));
        List<String> labels = new ArrayList<>();
        sweep.settings.forEach(s -> labels.add(s.label));
        assertEquals(List.of("grid 1", "grid 4", "grid 16", "jittered 1", "jittered 4", "jittered 16"), labels);
        assertFalse("every point is measured against the reference", sweep.hasBaseline);
        Setting jittered = sweep.settings.get(4);
        assertEquals(4, jittered.samples);
        assertTrue(jittered.pattern.isJittered());
        assertEquals(Sweeps.SEED, jittered.pattern.seed());
        assertEquals(RayOffsets.SCALED, jittered.offsets);
        assertEquals(SamplePattern.GRID, sweep.settings.get(0).pattern);
    }

    @Test
    public void theOffsetsSweepStartsFromTheFrameworksRule() {
        Sweep sweep = Sweeps.offsets();
        assertTrue(sweep.hasBaseline);
        assertEquals(RayOffsets.SCALED, sweep.baseline().offsets);
        assertEquals(RayOffsets.ERROR_BOUND, sweep.settings.get(1).offsets);
        assertEquals(RayOffsets.FIXED, sweep.settings.get(2).offsets);
        assertEquals(RayOffsets.NONE, sweep.settings.get(3).offsets);
        for (Setting s : sweep.settings) {
            assertEquals("at the scene's own samples", 0, s.samples);
        }
    }

    @Test
    public void availableSweepsComeInReportOrderAndTheRestAreNamedMissing() {
        List<Sweep> sweeps = Sweeps.available(Sweeps.SAMPLES);
        List<String> names = new ArrayList<>();
        sweeps.forEach(s -> names.add(s.name));
        assertEquals("samples", names.get(0));
        assertEquals(List.of("offsets", "depth", "acceleration"), names.subList(names.size() - 3, names.size()));
        List<String> expectedMissing = new ArrayList<>(Sweeps.ALL);
        expectedMissing.removeAll(names);
        assertEquals(expectedMissing, Sweeps.missing(sweeps));
        assertEquals(List.of("arithmetic", "intersection", "fresnel", "masking"),
                Sweeps.missing(List.of(Sweeps.samples(List.of(1)), Sweeps.offsets(), Sweeps.depth(), Sweeps.acceleration())));
    }

    @Test
    public void theAccelerationSweepComparesTheBvhWithLinearLoopsAtTheScenesOwnSamples() {
        Sweep sweep = Sweeps.acceleration();
        assertTrue(sweep.hasBaseline);
        assertEquals(ray.accel.Acceleration.BVH, sweep.baseline().acceleration);
        assertEquals(ray.accel.Acceleration.NONE, sweep.settings.get(1).acceleration);
        assertEquals(List.of("bvh", "linear"), List.of(sweep.settings.get(0).label, sweep.settings.get(1).label));
        for (Setting s : sweep.settings) {
            assertEquals(0, s.samples);
        }
    }

    @Test
    public void aSweepNeedsSettings() {
        try {
            new Sweep("empty", "?", List.of(), false);
            fail("an empty sweep was accepted");
        } catch (IllegalArgumentException e) {
            assertEquals("the sweep empty has no settings", e.getMessage());
        }
    }
}
