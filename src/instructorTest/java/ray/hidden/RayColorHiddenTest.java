package ray.hidden;

import static org.junit.Assert.assertEquals;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.render.RayTracer;
import ray.surface.Surface;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden ray-color cases: seeded random rays between two parallel planes (z = 0 facing up and z = 10
 * facing down), hits shaded to a color that encodes the hit's t and the depth, misses the background;
 * a chain of mirror rays bouncing between the planes through the tracer itself, each bounce at one
 * more depth; and an empty segment, which meets nothing.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class RayColorHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 SKY = new Vec3(0.25, 0.5, 0.75);

    /** The planes z = 0 (normal +z) and z = 10 (normal −z): the closest crossing within the ray's segment. */
    private static final class TwoPlanes extends Surface {
        @Override
        public boolean intersect(IntersectionRecord out, Ray ray) {
            double best = Double.POSITIVE_INFINITY;
            double plane = 0;
            for (double z : new double[] {0, 10}) {
                if (ray.direction.z != 0) {
                    double t = (z - ray.origin.z) / ray.direction.z;
                    if (ray.start < t && t < ray.end && t < best) {
                        best = t;
                        plane = z;
                    }
                }
            }
            if (best == Double.POSITIVE_INFINITY) {
                return false;
            }
            out.t = best;
            out.location = ray.pointAt(best);
            out.normal = new Vec3(0, 0, plane == 0 ? 1 : -1);
            out.surface = this;
            return true;
        }
    }

    private static RayTracer encoding(TwoPlanes planes) {
        RayTracer tracer = new RayTracer();
        tracer.use(planes, SKY, (hit, ray, depth) -> new Vec3(hit.t, depth, hit.normal.z));
        tracer.complete();
        return tracer;
    }

    @Test
    @Points(value = 4, visibility = Visibility.HIDDEN)
    public void randomRaysBetweenTwoPlanes() {
        TwoPlanes planes = new TwoPlanes();
        RayTracer tracer = encoding(planes);
        Random random = new Random(0x52415943L);
        for (int k = 0; k < 500; k++) {
            Vec3 origin = new Vec3(20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10, 14 * random.nextDouble() - 2);
            Vec3 direction = new Vec3(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1)
                    .times(0.1 + 3 * random.nextDouble());
            double start = random.nextInt(3) == 0 ? 0 : random.nextDouble();
            double end = random.nextInt(3) == 0 ? Double.POSITIVE_INFINITY : start + 20 * random.nextDouble();
            int depth = random.nextInt(6);
            Ray ray = new Ray(origin, direction, start, end);
            IntersectionRecord expectedHit = new IntersectionRecord();
            Vec3 expected = planes.intersect(expectedHit, ray.copy()) ? new Vec3(expectedHit.t, depth, expectedHit.normal.z) : SKY;
            Vec3 result = tracer.shadeRay(ray, depth);
            assertEquals("RayTracer.shadeRay of " + ray + " at depth " + depth + " (the color encodes the hit's t, the depth and the normal's z;"
                    + " the background is " + SKY + ")", expected, result);
        }
    }

    /** Bouncing between the planes through the tracer, each bounce one depth more, up to depth 6, then the last hit's t. */
    @Test
    @Points(value = 3, visibility = Visibility.HIDDEN)
    public void aChainOfMirrorRays() {
        TwoPlanes planes = new TwoPlanes();
        RayTracer tracer = new RayTracer();
        tracer.use(planes, SKY, (hit, ray, depth) -> {
            if (depth == 6) {
                return new Vec3(depth, hit.location.x, 1);
            }
            Vec3 d = ray.direction;
            Vec3 mirrored = new Vec3(d.x, d.y, -d.z);
            return tracer.shadeRay(new Ray(hit.location, mirrored, 1e-9, Double.POSITIVE_INFINITY), depth + 1).times(0.5);
        });
        tracer.complete();
        // From (0, 0, 5) along (1, 0, −5): hits at x = 1, 3, 5, …; the seventh hit (depth 6) is at x = 13.
        Vec3 result = tracer.shadeRay(new Ray(new Vec3(0, 0, 5), new Vec3(1, 0, -5)), 0);
        double half6 = Math.pow(0.5, 6);
        assertEquals("six mirror bounces, each halving: the seventh hit's (depth, x, 1) / 64", new Vec3(6 * half6, 13 * half6, half6), result);
    }

    /** A ray whose segment is empty (start = end) meets nothing: the background. */
    @Test
    @Points(value = 1, visibility = Visibility.HIDDEN)
    public void anEmptySegmentMeetsNothing() {
        Vec3 result = encoding(new TwoPlanes()).shadeRay(new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1), 2, 2), 0);
        assertEquals("a ray of empty segment: the background", SKY, result);
    }
}
