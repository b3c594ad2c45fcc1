package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;

import java.util.Random;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Sphere;

/**
 * Rays along a sphere's pole axes (through the center, along ±x, ±y, ±z) and rays from the center:
 * the normal is finite and unit length. Along an axis it is exactly that axis (l = 0 and the offset
 * from the center has two exact zeros); from the center it is the ray's direction.
 */
public class SpherePoleAndCenterTest {
    private static final Vec3[] AXES = {new Vec3(1, 0, 0), new Vec3(-1, 0, 0), new Vec3(0, 1, 0), new Vec3(0, -1, 0), new Vec3(0, 0, 1), new Vec3(0, 0, -1)};

    /**
     * From 5r out on an axis, from the center and from r/2 behind it, heading along the axis: the
     * first pole ahead is hit, with exactly ± that axis as normal. Centers near and far (1e6) from the
     * world origin; radii 1e-3…1e3; direction lengths 1, 0.3, 7.
     */
    @Test
    public void rayAlongThePoleAxisHitsThePoleWithExactlyTheAxisAsNormal() {
        Vec3[] centers = {new Vec3(3, -2, 5), new Vec3(1e6, -2e6, 5e5)};
        for (Vec3 center : centers) {
            for (double r : new double[] {1e-3, 1, 1e3}) {
                for (Vec3 axis : AXES) {
                    for (double start : new double[] {-5, 0, -0.5}) {
                        for (double length : new double[] {1, 0.3, 7}) {
                            // The ray runs along +axis from center + start·r·axis. From outside (start −5) the
                            // first pole is center − r·axis; from inside it is center + r·axis.
                            Ray ray = new Ray(center.plus(axis.times(start * r)), axis.times(length));
                            double pole = start < -1 ? -1 : 1;
                            IntersectionRecord out = new IntersectionRecord();
                            String what = "r " + r + ", " + ray;
                            assertTrue(what, new Sphere(center, r).intersect(out, ray));
                            assertVec(what, axis.times(pole), out.normal, 0);
                            // (pole − start)·r/length, to the rounding of the origin's coordinates (ulps of |center| + 5r).
                            double slack = 8 * Math.ulp(center.maxAbs() + 5 * r) / length;
                            assertEquals(what, (pole - start) * r / length, out.t, slack);
                            assertVec(what, center.plus(axis.times(pole * r)), out.location, 2 * Math.ulp(center.maxAbs() + r));
                        }
                    }
                }
            }
        }
    }

    /**
     * From the center in 2,000 seeded directions (lengths 10^U(−2, 2)), radii 10^U(−3, 6), centers up to
     * 10 radii from the world origin: a unit normal equal to d/|d| (to 1e-14: the normal is
     * normalize(p − c), and p = c + t·d rounds at ulps of |c| ≤ 10r).
     */
    @Test
    public void rayFromTheCenterHasTheUnitDirectionAsNormal() {
        Random random = new Random(801);
        for (int i = 0; i < 2_000; i++) {
            double r = Math.pow(10, -3 + 9 * random.nextDouble());
            Vec3 center = unit(random).times(10 * r * random.nextDouble());
            Vec3 direction = unit(random).times(Math.pow(10, -2 + 4 * random.nextDouble()));
            Ray ray = new Ray(center, direction);
            IntersectionRecord out = new IntersectionRecord();
            String what = "r " + r + ", " + ray;
            assertTrue(what, new Sphere(center, r).intersect(out, ray));
            assertTrue(what + ": normal " + out.normal, out.normal.isFinite());
            assertEquals(what, 1, out.normal.length(), 4 * Math.ulp(1.0));
            assertVec(what, direction.normalized(), out.normal, 1e-14);
        }
    }

    private static Vec3 unit(Random random) {
        return new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalized();
    }
}
