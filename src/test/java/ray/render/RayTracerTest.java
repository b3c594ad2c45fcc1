package ray.render;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.util.ArrayList;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Surface;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks RayTracer.shadeRay with a scene made by hand: a surface hit wherever its plane z = 0 lies
 * within the ray's segment, a background color, and a shading that notes what it was asked.
 */
@Points(1)
public class RayTracerTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 SKY = v(0.1, 0.3, 0.5);

    /** The plane z = 0, facing +z, hit where the ray crosses it within its segment; it notes the segments it was asked about. */
    private static final class Floor extends Surface {
        final List<double[]> segments = new ArrayList<>();

        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            segments.add(new double[] {ray.start, ray.end});
            if (ray.direction.z == 0) {
                return false;
            }
            double t = -ray.origin.z / ray.direction.z;
            if (!(ray.start < t && t < ray.end)) {
                return false;
            }
            out.t = t;
            out.location = ray.pointAt(t);
            out.normal = v(0, 0, 1);
            out.surface = this;
            return true;
        }
    }

    /** What the tracer asked to have shaded. */
    private static final class Asked {
        IntersectionRecord hit;
        Ray ray;
        int depth = -1;
        int times;
    }

    private static RayTracer tracer(Floor floor, Asked asked, Vec3 color) {
        RayTracer tracer = new RayTracer();
        tracer.use(floor, SKY, (hit, ray, depth) -> {
            asked.hit = hit;
            asked.ray = ray;
            asked.depth = depth;
            asked.times++;
            return color;
        });
        tracer.complete();
        return tracer;
    }

    /** A ray that meets the floor brings back what shading its hit gives, for exactly that hit and ray. */
    @Test
    @Points(2)
    public void aHitIsShaded() {
        Floor floor = new Floor();
        Asked asked = new Asked();
        Ray ray = new Ray(v(1, 2, 4), v(0, 0, -2));
        Vec3 result = tracer(floor, asked, v(0.2, 0.4, 0.6)).shadeRay(ray, 0);
        assertEquals("RayTracer.shadeRay of a ray that meets a surface whose hit shades to (0.2, 0.4, 0.6)", v(0.2, 0.4, 0.6), result);
        assertEquals("shade(hit, ray, depth) was asked " + asked.times + " times for one ray; expected once", 1, asked.times);
        assertEquals("the hit passed to shade has t", 2, asked.hit.t, 1e-12);
        String shown = "shade(hit, ray, depth) was given the ray " + asked.ray + "; expected the one traced, " + ray;
        assertEquals(shown, ray.origin, asked.ray.origin);
        assertEquals(shown, ray.direction, asked.ray.direction);
        assertSame("the hit passed to shade is not the surface's", floor, asked.hit.surface);
    }

    /** A ray that meets nothing brings back the background color, and shades nothing. */
    @Test
    @Points(2)
    public void aMissIsTheBackground() {
        Floor floor = new Floor();
        Asked asked = new Asked();
        Vec3 result = tracer(floor, asked, v(1, 1, 1)).shadeRay(new Ray(v(0, 0, 4), v(0, 0, 1)), 0);
        assertEquals("RayTracer.shadeRay of a ray that meets nothing: the background color", SKY, result);
        assertEquals("a ray that meets nothing has nothing to shade, but shade was asked", 0, asked.times);
    }

    /** The depth is passed on as it is: a mirror ray of depth 3 is shaded at depth 3. */
    @Test
    public void theDepthIsPassedOn() {
        Floor floor = new Floor();
        Asked asked = new Asked();
        tracer(floor, asked, v(1, 1, 1)).shadeRay(new Ray(v(0, 0, 4), v(0, 1, -1)), 3);
        assertEquals("shade was asked at depth", 3, asked.depth);
    }

    /** The ray's own segment decides: a floor beyond the ray's end is not hit, and the search sees the segment unchanged. */
    @Test
    @Points(2)
    public void theRaysSegmentIsKept() {
        Floor floor = new Floor();
        Asked asked = new Asked();
        Vec3 result = tracer(floor, asked, v(1, 1, 1)).shadeRay(new Ray(v(0, 0, 4), v(0, 0, -1), 0.5, 3), 0);
        assertEquals("a ray whose segment ends before the surface (t = 4 beyond end 3) meets nothing", SKY, result);
        assertTrue("the scene was never searched", !floor.segments.isEmpty());
        assertEquals("the segment's start as the search saw it", 0.5, floor.segments.get(0)[0], 0);
        assertEquals("the segment's end as the search saw it", 3, floor.segments.get(0)[1], 0);
    }

    /**
     * A mirror: shading a hit traces another ray through the same tracer (depth + 1), which meets
     * nothing here. Each ray gets its own answer: the mirror's half of the sky.
     */
    @Test
    @Points(2)
    public void aMirrorRayComesBackThroughTheTracer() {
        Floor floor = new Floor();
        RayTracer tracer = new RayTracer();
        List<Integer> depths = new ArrayList<>();
        tracer.use(floor, SKY, (hit, ray, depth) -> {
            depths.add(depth);
            Vec3 up = v(ray.direction.x, ray.direction.y, -ray.direction.z);
            return tracer.shadeRay(new Ray(hit.location, up, 1e-9, Double.POSITIVE_INFINITY), depth + 1).times(0.5);
        });
        tracer.complete();
        Vec3 result = tracer.shadeRay(new Ray(v(0, 0, 4), v(1, 0, -1)), 0);
        assertEquals("a mirror's hit, half the sky it reflects", SKY.times(0.5), result);
        assertEquals("the depths shaded", List.of(0), depths);
    }

    /**
     * The course's limit on a path of mirror rays: with a limit of 5, a ray of depth 5 (or more) brings
     * back black without a search or a shading; one of depth 4 is traced as any other.
     */
    @Test
    @Points(2)
    public void aRayAtTheDepthLimitIsBlackAndUntraced() {
        Floor floor = new Floor();
        Asked asked = new Asked();
        RayTracer tracer = new RayTracer();
        tracer.use(floor, SKY, (hit, ray, depth) -> {
            asked.times++;
            asked.depth = depth;
            return v(0.2, 0.4, 0.6);
        }, 5);
        tracer.complete();
        Ray down = new Ray(v(0, 0, 3), v(0, 0, -1));
        assertEquals("shadeRay(ray, 5) with maxDepth() = 5: black", Vec3.ZERO, tracer.shadeRay(down, 5));
        assertEquals("shadeRay(ray, 7) with maxDepth() = 5: black", Vec3.ZERO, tracer.shadeRay(down, 7));
        assertEquals("a ray at the limit is not traced: the scene was searched", 0, floor.segments.size());
        assertEquals("a ray at the limit is not traced: shade was asked", 0, asked.times);
        assertEquals("shadeRay(ray, 4) with maxDepth() = 5: the shaded hit", v(0.2, 0.4, 0.6), tracer.shadeRay(down, 4));
        assertEquals(4, asked.depth);
    }
}
