package ray.accel;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Mesh;
import ray.surface.MeshData;

/**
 * The hierarchy's answer is the linear loop's, exactly: for seeded random rays through meshes built
 * to be hard (duplicate triangles, so ties in t; grids of coplanar triangles sharing edges and
 * vertices, lying in the faces of their own boxes; rays aimed at vertices and edges, rays in a grid's
 * plane, rays ending exactly at a hit), the closest hit names the same triangle with the same t bits,
 * and the any-hit query agrees on whether there is a hit.
 */
public class BvhAgreesWithLinearLoopTest {
    private static final long SEED = 20261125L;

    /** Triangles as a flat list of corner positions (9 numbers each). */
    private static final class Soup {
        final List<double[]> triangles = new ArrayList<>();

        void add(Vec3 a, Vec3 b, Vec3 c) {
            triangles.add(new double[] {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z});
        }

        /** A side×side grid of unit squares (two triangles each) in the plane of two axes, at a fixed third coordinate. */
        void grid(int side, double fixed, int axis, double offset) {
            for (int i = 0; i < side; i++) {
                for (int j = 0; j < side; j++) {
                    Vec3 a = onPlane(axis, i + offset, j + offset, fixed);
                    Vec3 b = onPlane(axis, i + 1 + offset, j + offset, fixed);
                    Vec3 c = onPlane(axis, i + 1 + offset, j + 1 + offset, fixed);
                    Vec3 d = onPlane(axis, i + offset, j + 1 + offset, fixed);
                    add(a, b, c);
                    add(a, c, d);
                }
            }
        }

        private static Vec3 onPlane(int axis, double s, double t, double fixed) {
            return axis == 0 ? new Vec3(fixed, s, t) : axis == 1 ? new Vec3(s, fixed, t) : new Vec3(s, t, fixed);
        }

        Mesh mesh() {
            int n = triangles.size();
            double[] positions = new double[9 * n];
            int[] indices = new int[3 * n];
            for (int k = 0; k < n; k++) {
                System.arraycopy(triangles.get(k), 0, positions, 9 * k, 9);
                for (int c = 0; c < 3; c++) {
                    indices[3 * k + c] = 3 * k + c;
                }
            }
            Mesh mesh = new Mesh();
            mesh.setData(new MeshData(positions, new double[0], indices, null));
            mesh.complete();
            return mesh;
        }

        Vec3 corner(int triangle, int c) {
            double[] t = triangles.get(triangle);
            return new Vec3(t[3 * c], t[3 * c + 1], t[3 * c + 2]);
        }
    }

    private static Soup hardSoup(Random random) {
        Soup soup = new Soup();
        for (int k = 0; k < 400; k++) {
            Vec3 a = point(random, 10);
            soup.add(a, a.plus(point(random, 1.5)), a.plus(point(random, 1.5)));
        }
        soup.grid(6, 0, 2, -3);
        soup.grid(6, 2, 0, -3);
        soup.grid(6, -1, 1, -3);
        // The same grid again, later in the file: every hit on it ties with the earlier copy.
        soup.grid(6, 0, 2, -3);
        // Duplicates of random triangles too.
        for (int k = 0; k < 40; k++) {
            double[] t = soup.triangles.get(random.nextInt(400));
            soup.triangles.add(t.clone());
        }
        return soup;
    }

    private static Vec3 point(Random random, double half) {
        return new Vec3(half * (2 * random.nextDouble() - 1), half * (2 * random.nextDouble() - 1), half * (2 * random.nextDouble() - 1));
    }

    private static List<Ray> hardRays(Random random, Soup soup) {
        List<Ray> rays = new ArrayList<>();
        int n = soup.triangles.size();
        for (int k = 0; k < 3000; k++) {
            Vec3 origin = point(random, 25);
            Vec3 target;
            switch (k % 4) {
                case 0:
                    target = point(random, 10);
                    break;
                case 1:
                    target = soup.corner(random.nextInt(n), random.nextInt(3)); // through a vertex
                    break;
                case 2:
                    target = soup.corner(random.nextInt(n), 0).plus(soup.corner(random.nextInt(n), 1)).times(0.5);
                    break;
                default:
                    // In the plane z = 0 of the first grid, or along a grid line.
                    origin = new Vec3(origin.x, random.nextBoolean() ? 0 : Math.rint(origin.y), 0);
                    target = new Vec3(random.nextInt(7) - 3, random.nextInt(7) - 3, 0);
                    break;
            }
            rays.add(new Ray(origin, target.minus(origin)));
        }
        return rays;
    }

    @Test
    public void closestAndAnyHitAgreeWithTheLinearLoop() {
        Random random = new Random(SEED);
        Soup soup = hardSoup(random);
        Mesh mesh = soup.mesh();
        assertTrue("a real tree: " + mesh.treeNodes(), mesh.treeNodes() > 100);
        int hits = 0;
        int ties = 0;
        for (Ray ray : hardRays(random, soup)) {
            IntersectionRecord linear = new IntersectionRecord();
            boolean linearHit = mesh.closestHitLinear(linear, ray, null);
            check(mesh, ray, linearHit, linear);
            if (linearHit) {
                hits++;
                // The same ray ending exactly at the hit (nothing at t counts), and just past it.
                check(mesh, new Ray(ray.origin, ray.direction, ray.start, linear.t), null);
                Ray pastIt = new Ray(ray.origin, ray.direction, ray.start, Math.nextUp(linear.t));
                IntersectionRecord again = new IntersectionRecord();
                assertTrue(mesh.closestHitLinear(again, pastIt, null));
                check(mesh, pastIt, true, again);
                ties += tiesOf(mesh, ray, linear) ? 1 : 0;
            }
        }
        assertTrue("enough hits to judge: " + hits, hits > 1000);
        assertTrue("ties in t met and kept: " + ties, ties > 50);
    }

    private static void check(Mesh mesh, Ray ray, IntersectionRecord ignored) {
        IntersectionRecord linear = new IntersectionRecord();
        check(mesh, ray, mesh.closestHitLinear(linear, ray, null), linear);
    }

    private static void check(Mesh mesh, Ray ray, boolean linearHit, IntersectionRecord linear) {
        IntersectionRecord fast = new IntersectionRecord();
        assertEquals(ray.toString(), linearHit, mesh.closestHit(fast, ray, null));
        assertEquals(ray.toString(), linearHit, mesh.anyHit(ray, null));
        if (linearHit) {
            assertSame(ray.toString(), linear.surface, fast.surface);
            assertEquals(ray.toString(), Double.doubleToRawLongBits(linear.t), Double.doubleToRawLongBits(fast.t));
        }
    }

    /** Whether another triangle is hit at exactly the same t (so the file order decided). */
    private static boolean tiesOf(Mesh mesh, Ray ray, IntersectionRecord hit) {
        int at = 0;
        for (ray.surface.Surface s : mesh.children()) {
            IntersectionRecord r = new IntersectionRecord();
            if (s.intersect(r, ray) && r.t == hit.t) {
                at++;
            }
        }
        return at > 1;
    }
}
