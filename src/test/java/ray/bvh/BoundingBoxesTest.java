package ray.bvh;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.RandomVectors;
import ray.testing.StudentTaskRule;

/** The boxes of a sphere and of a triangle: hand-computed cases, flat and degenerate triangles, and seeded random ones. */
@Points(1)
public class BoundingBoxesTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static void sphere(Vec3 center, double radius, Vec3 min, Vec3 max, String why) {
        Box box = new BoundingBoxes().ofSphere(center, radius);
        String call = "ofSphere(" + center + ", " + radius + ")";
        assertNotNull(call + " returned null; expected a box", box);
        assertEquals(call + " returned " + box + "; expected the box from " + min + " to " + max + Hints.fix(why), new Box(min, max), box);
    }

    private static void triangle(Vec3 a, Vec3 b, Vec3 c, Vec3 min, Vec3 max, String why) {
        Box box = new BoundingBoxes().ofTriangle(a, b, c);
        String call = "ofTriangle(" + a + ", " + b + ", " + c + ")";
        assertNotNull(call + " returned null; expected a box", box);
        assertEquals(call + " returned " + box + "; expected the box from " + min + " to " + max + Hints.fix(why), new Box(min, max), box);
    }

    @Test
    public void aSphereReachesItsRadiusAlongEachAxis() {
        sphere(v(0, 0, 0), 1, v(-1, -1, -1), v(1, 1, 1), " (center ∓ r on each axis)");
        sphere(v(1, 2, 3), 0.5, v(0.5, 1.5, 2.5), v(1.5, 2.5, 3.5), " (center ∓ r on each axis)");
    }

    @Test
    public void aMovedSphereMovesItsBox() {
        sphere(v(-1000, 7, 0.25), 2, v(-1002, 5, -1.75), v(-998, 9, 2.25), " (the box is around the sphere's center, not the origin)");
    }

    @Test
    public void aTrianglesBoxRunsFromItsSmallestToItsLargestCoordinates() {
        triangle(v(1, 5, -2), v(3, -1, 0), v(-2, 2, 4), v(-2, -1, -2), v(3, 5, 4), " (each axis separately: the smallest and largest of three)");
        triangle(v(-2, 2, 4), v(1, 5, -2), v(3, -1, 0), v(-2, -1, -2), v(3, 5, 4), " (the same triangle, its corners in another order)");
    }

    @Test
    public void aTriangleInAnAxisPlaneHasAFlatBox() {
        triangle(v(0, 0, 2), v(1, 0, 2), v(0, 3, 2), v(0, 0, 2), v(1, 3, 2), " (min.z = max.z = 2: no padding)");
    }

    @Test
    public void aDegenerateTriangleStillGetsTheBoxOfItsCorners() {
        triangle(v(0, 0, 0), v(1, 1, 1), v(2, 2, 2), v(0, 0, 0), v(2, 2, 2), " (corners on one line)");
        triangle(v(5, -3, 1), v(5, -3, 1), v(5, -3, 1), v(5, -3, 1), v(5, -3, 1), " (a triangle at one point has a box of one point)");
    }

    @Test
    public void randomSpheresAndTriangles() {
        Random random = new Random(4620);
        for (int i = 0; i < 200; i++) {
            Vec3 c = RandomVectors.randomVec(random, 1e3);
            double r = Math.exp(12 * random.nextDouble() - 6);
            Vec3 reach = v(r, r, r);
            sphere(c, r, c.minus(reach), c.plus(reach), "");
            Vec3 a = RandomVectors.randomVec(random, 10);
            Vec3 b = RandomVectors.randomVec(random, 10);
            Vec3 d = RandomVectors.randomVec(random, 10);
            triangle(a, b, d, v(Math.min(a.x, Math.min(b.x, d.x)), Math.min(a.y, Math.min(b.y, d.y)), Math.min(a.z, Math.min(b.z, d.z))),
                    v(Math.max(a.x, Math.max(b.x, d.x)), Math.max(a.y, Math.max(b.y, d.y)), Math.max(a.z, Math.max(b.z, d.z))), "");
        }
    }
}
