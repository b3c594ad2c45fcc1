package ray.render;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.HitGeometry;
import ray.surface.Sphere;

/**
 * The three rules for where secondary rays start, which the accuracy report compares, on a hit
 * whose numbers are exact: the top (0, 0, 1) of the unit sphere at the origin, so the offset scale
 * is |center| + radius = 1 and the offsets are powers of two.
 */
public class RayOffsetsTest {
    private static HitGeometry topOfUnitSphere() {
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 1;
        hit.location = v(0, 0, 1);
        hit.normal = v(0, 0, 1);
        hit.surface = new Sphere(v(0, 0, 0), 1);
        return hit.surface.hitGeometry(hit);
    }

    @Test
    public void noneStartsAtTheHitPoint() {
        Ray shadow = RayOffsets.NONE.shadowRay(topOfUnitSphere(), v(0, 0, 5));
        assertEquals(v(0, 0, 1), shadow.origin);
        assertEquals(v(0, 0, 4), shadow.direction);
        assertEquals(0, shadow.start, 0);
        assertEquals(SecondaryRays.SHADOW_END, shadow.end, 0);
        Ray reflected = RayOffsets.NONE.reflectionRay(topOfUnitSphere(), v(0, 0, 2));
        assertEquals(v(0, 0, 1), reflected.origin);
        assertEquals(0, reflected.start, 0);
    }

    @Test
    public void fixedSkipsTheFirstMillionthOfADistanceUnit() {
        Ray shadow = RayOffsets.FIXED.shadowRay(topOfUnitSphere(), v(0, 0, 5));
        assertEquals(v(0, 0, 1), shadow.origin);
        assertEquals("t_min = 1e-6 / |d| with |d| = 4", 1e-6 / 4, shadow.start, 0);
        assertEquals(SecondaryRays.SHADOW_END, shadow.end, 0);
        Ray reflected = RayOffsets.FIXED.reflectionRay(topOfUnitSphere(), v(0, 0, 2));
        assertEquals(1e-6 / 2, reflected.start, 0);
        assertEquals(Double.POSITIVE_INFINITY, reflected.end, 0);
    }

    @Test
    public void scaledStartsOffTheSurfaceByUlpsOfItsScale() {
        // 1024·2⁻⁵³·1 = 2⁻⁴³ for double; 1024·2⁻²⁴·1 = 2⁻¹⁴ for float.
        assertEquals(v(0, 0, 1 + 0x1p-43), RayOffsets.SCALED.reflectionRay(topOfUnitSphere(), v(0, 0, 2)).origin);
        assertEquals(v(0, 0, 1 + 0x1p-14), RayOffsets.SCALED_FOR_FLOAT.reflectionRay(topOfUnitSphere(), v(0, 0, 2)).origin);
        assertEquals("toward the side the ray leaves to", v(0, 0, 1 - 0x1p-14),
                RayOffsets.SCALED_FOR_FLOAT.reflectionRay(topOfUnitSphere(), v(0, 0, -2)).origin);
        Ray shadow = RayOffsets.SCALED_FOR_FLOAT.shadowRay(topOfUnitSphere(), v(0, 0, 5));
        assertEquals(v(0, 0, 1 + 0x1p-14), shadow.origin);
        assertEquals(v(0, 0, 4 - 0x1p-14), shadow.direction);
        Ray framework = SecondaryRays.shadowRay(topOfUnitSphere(), v(0, 0, 5));
        Ray scaled = RayOffsets.SCALED.shadowRay(topOfUnitSphere(), v(0, 0, 5));
        assertEquals("SCALED is the framework's rule", framework.origin, scaled.origin);
        assertEquals(framework.direction, scaled.direction);
        assertEquals(framework.start, scaled.start, 0);
        assertEquals(framework.end, scaled.end, 0);
    }

    @Test
    public void everyRenderUsesTheScaledRule() {
        ray.scene.Scene scene = TestScenes.scene(new RecordingCamera(), 2, 2);
        scene.complete();
        assertEquals(RayOffsets.SCALED, RenderPlan.of(scene).offsets());
        assertEquals(RayOffsets.NONE, RenderPlan.of(scene).withOffsets(RayOffsets.NONE).offsets());
        assertEquals("offsets do not change the effects", RenderPlan.of(scene).describe(),
                RenderPlan.of(scene).withOffsets(RayOffsets.NONE).describe());
    }
}
