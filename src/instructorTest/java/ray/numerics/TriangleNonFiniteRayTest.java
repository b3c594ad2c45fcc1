package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;

import java.util.Random;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Mesh;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * NaN or infinite values in a ray (origin, direction, start, end) meeting a triangle or a closed
 * mesh: no exception, a miss, the record untouched. Each case starts from a ray that hits (checked),
 * then puts NaN, +∞ or −∞ into one to three of its origin and direction coordinates, or NaN into its
 * start or end, or start = +∞ or end = −∞. Segments start at 0 or at −10, since a segment that
 * reaches below 0 accepts the t = 0 that an infinite direction produces (origin + 0·∞ is NaN).
 * 20,000 random triangles × 5 corrupted rays, and 20,000 corrupted rays at an icosphere: none hit.
 * Also a zero direction, and an infinite direction along a sliver, which reaches the solution's
 * exact parallel test (it threw NumberFormatException there before that test checked for
 * non-finite directions; random rays almost never get there).
 */
public class TriangleNonFiniteRayTest {
    private static final double[] BAD = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};

    @Test
    public void corruptedRaysMissATriangle() {
        Random random = new Random(31);
        for (int i = 0; i < 20_000; i++) {
            Triangle t = new Triangle(randomPoint(random, 10), randomPoint(random, 10), randomPoint(random, 10));
            Vec3 target = t.getV0().times(0.2).plus(t.getV1().times(0.3)).plus(t.getV2().times(0.5));
            Vec3 origin = randomPoint(random, 20);
            Ray good = new Ray(origin, target.minus(origin), random.nextBoolean() ? 0 : -10, Double.POSITIVE_INFINITY);
            if (DegenerateTriangles.hasNoArea(t) || !t.intersect(new IntersectionRecord(), good)) {
                // Guards the cases below: only rays that hit before the corruption count (all but slivers).
                continue;
            }
            for (int k = 0; k < 5; k++) {
                assertMiss(t, corrupt(good, random));
            }
        }
    }

    @Test
    public void corruptedRaysMissAClosedMesh() {
        Random random = new Random(32);
        Vec3 center = new Vec3(3, -2, 5);
        Mesh mesh = ClosedMesh.mesh(ClosedMesh.data(center, 2));
        for (int i = 0; i < 20_000; i++) {
            Vec3 origin = center.plus(randomPoint(random, 0.5));
            Ray good = new Ray(origin, randomPoint(random, 1), random.nextBoolean() ? 0 : -10, Double.POSITIVE_INFINITY);
            assertTrue("a ray from inside must hit the icosphere", mesh.intersect(new IntersectionRecord(), good));
            assertMiss(mesh, corrupt(good, random));
        }
    }

    @Test
    public void zeroDirectionMisses() {
        Triangle t = new Triangle(new Vec3(0, 0, 2), new Vec3(4, 0, 2), new Vec3(0, 2, 2));
        assertMiss(t, new Ray(new Vec3(1, 0.5, 5), Vec3.ZERO, -10, 10));
        assertMiss(t, new Ray(new Vec3(1, 0.5, 2), Vec3.ZERO, -10, 10));
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(t.intersect(out, new Ray(new Vec3(1, 0.5, 5), new Vec3(0, 0, -1))));
        assertEquals(3, out.t, 0);
    }

    @Test
    public void infiniteDirectionAlongASliverMisses() {
        // Along x, the triangle projects onto the yz plane as a sliver of area 5e-18 with a vertex on
        // the ray: the edge tests pass and det is tiny, which sends the solution to its exact
        // parallel test. That test must not choke on the infinite direction.
        Triangle sliver = new Triangle(new Vec3(-1, -1, 0), new Vec3(1, 1, 1e-17), new Vec3(5, 0, 0));
        for (double bad : BAD) {
            assertMiss(sliver, new Ray(new Vec3(-10, 0, 0), new Vec3(bad, 0, 0)));
            assertMiss(sliver, new Ray(new Vec3(-10, 0, 0), new Vec3(bad, 0, 0), -10, 10));
        }
        IntersectionRecord out = new IntersectionRecord();
        assertTrue("the same ray with direction (1, 0, 0) grazes the sliver at its vertex (5, 0, 0)",
                sliver.intersect(out, new Ray(new Vec3(-10, 0, 0), new Vec3(1, 0, 0))));
        assertEquals(15, out.t, 1e-12);
    }

    /** The ray with one to three coordinates of origin and direction made non-finite, or with a NaN or empty segment. */
    private static Ray corrupt(Ray ray, Random random) {
        if (random.nextInt(5) == 0) {
            // NaN, or the infinity that empties the segment (start −∞ or end +∞ is a fine unbounded segment).
            boolean nan = random.nextBoolean();
            return random.nextBoolean()
                    ? new Ray(ray.origin, ray.direction, nan ? Double.NaN : Double.POSITIVE_INFINITY, ray.end)
                    : new Ray(ray.origin, ray.direction, ray.start, nan ? Double.NaN : Double.NEGATIVE_INFINITY);
        }
        double[] values = {ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z};
        int count = 1 + random.nextInt(3);
        for (int c = 0; c < count; c++) {
            values[random.nextInt(6)] = BAD[random.nextInt(3)];
        }
        return new Ray(new Vec3(values[0], values[1], values[2]), new Vec3(values[3], values[4], values[5]), ray.start, ray.end);
    }

    private static void assertMiss(Surface surface, Ray ray) {
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        boolean hit;
        try {
            hit = surface.intersect(out, ray);
        } catch (RuntimeException e) {
            throw new AssertionError(surface + ", " + ray + ": threw " + e, e);
        }
        if (hit) {
            fail(ray + " has a non-finite value, yet hit " + surface + " at t = " + out.t + ", " + out.location);
        }
        assertUntouched(before, out);
    }

    private static Vec3 randomPoint(Random random, double extent) {
        return new Vec3(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1));
    }
}
