package ray.bvh;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden tree cases, all over squares (no other task's code): builds over primitives in one plane, on
 * one line, all at one place, and spread from 1e-6 to 1e6; searches of axis-aligned grids by rays with
 * zero direction components and rays that start on a face; a chain-shaped tree a thousand nodes deep;
 * a segment that ends exactly at a hit; a scene ten million units from the origin.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class BvhHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass()).withTimeoutSeconds(120);

    private static BvhNode built(BvhTree tree, Squares.Square[] squares, String what) {
        Box[] boxes = Squares.boxes(squares);
        tree.prepare(squares, boxes);
        BvhNode root = tree.build(0, squares.length);
        assertNull("Over " + what + ": " + TreeInvariants.firstProblem(root, tree, boxes), TreeInvariants.firstProblem(root, tree, boxes));
        return root;
    }

    private static void agree(Squares.Square[] squares, BvhTree tree, BvhNode root, Ray ray, String what) {
        IntersectionRecord expected = Squares.linear(squares, ray);
        IntersectionRecord out = new IntersectionRecord();
        boolean hit = tree.closestHit(root, out, ray.copy());
        String call = "Over " + what + ", closestHit(ray from " + ray.origin + " along " + ray.direction + ", (" + ray.start + ", " + ray.end + "))";
        assertEquals(call + " returned " + hit + (hit ? " at t " + out.t : "") + "; the plain loop " + (expected == null ? "misses"
                : "hits square #" + (int) expected.texU + " at t " + expected.t), expected != null, hit);
        if (expected != null) {
            assertEquals(call + " found t " + out.t + "; the closest hit is at t " + expected.t, expected.t, out.t, 0);
        }
        assertEquals("Over " + what + ", anyHit of the same ray", expected != null, tree.anyHit(root, ray.copy()));
    }

    @Test
    public void buildsOverDegenerateSets() {
        Random random = new Random(77);
        Squares.Square[] plane = new Squares.Square[3000];
        Squares.Square[] line = new Squares.Square[500];
        Squares.Square[] point = new Squares.Square[300];
        Squares.Square[] scales = new Squares.Square[2000];
        for (int i = 0; i < plane.length; i++) {
            plane[i] = new Squares.Square(i, 2, v(10 * random.nextDouble(), 10 * random.nextDouble(), 0.5), 0.05);
        }
        for (int i = 0; i < line.length; i++) {
            line[i] = new Squares.Square(i, 0, v(i % 7 == 0 ? 3 : random.nextDouble() * 100, 0, 0), 0.2);
        }
        for (int i = 0; i < point.length; i++) {
            point[i] = new Squares.Square(i, i % 3, v(-1, 2, -3), 0.1 + i % 5);
        }
        for (int i = 0; i < scales.length; i++) {
            double scale = Math.pow(10, 12 * random.nextDouble() - 6);
            scales[i] = new Squares.Square(i, random.nextInt(3), v(scale * random.nextGaussian(), scale, -scale), scale / 10);
        }
        built(new BvhTree(), plane, "3,000 squares in the plane z = 0.5");
        built(new BvhTree(), line, "500 squares along the x axis, a seventh of them at x = 3");
        built(new BvhTree(), point, "300 squares all centered at (−1, 2, −3)");
        built(new BvhTree(), scales, "2,000 squares from 1e-6 to 1e6 in size and place");
    }

    @Test
    public void axisRaysThroughAGridOfSquares() {
        // A 12 × 12 × 3 grid of squares facing z, at integer x and y and z = 0, 1, 2: rays along the axes
        // and in the grid's planes meet faces exactly, where the slab distances are 0 · ∞.
        Squares.Square[] grid = new Squares.Square[12 * 12 * 3];
        int id = 0;
        for (int z = 0; z < 3; z++) {
            for (int y = 0; y < 12; y++) {
                for (int x = 0; x < 12; x++) {
                    grid[id] = new Squares.Square(id, 2, v(x, y, z), 0.5);
                    id++;
                }
            }
        }
        BvhNode[] root = new BvhNode[1];
        BvhTree tree = Squares.treeByPlace(grid, root);
        BvhTree yours = new BvhTree();
        BvhNode yourRoot = built(yours, grid, "a 12 × 12 × 3 grid");
        for (int x = -1; x <= 12; x++) {
            for (int y = -1; y <= 12; y++) {
                Ray down = new Ray(v(x + 0.5 * (y % 2), y, 5), v(0, 0, -1), 0, Double.POSITIVE_INFINITY);
                agree(grid, tree, root[0], down, "a grid, a ray straight down");
                agree(grid, yours, yourRoot, down, "a grid (your tree), a ray straight down");
                Ray across = new Ray(v(-3, y - 0.5, 1), v(1, 0, 0), 0, Double.POSITIVE_INFINITY);
                agree(grid, yours, yourRoot, across, "a grid (your tree), a ray in the plane z = 1, along x");
            }
        }
    }

    @Test
    public void aRayStartingOnAFaceAndASegmentEndingAtAHit() {
        Squares.Square[] row = new Squares.Square[40];
        for (int i = 0; i < row.length; i++) {
            row[i] = new Squares.Square(i, 0, v(i, 0, 0), 1);
        }
        BvhTree yours = new BvhTree();
        BvhNode root = built(yours, row, "40 squares in a row along x");
        agree(row, yours, root, new Ray(v(0, 0, 0), v(1, 0, 0), 0, Double.POSITIVE_INFINITY), "a row, a ray starting on square #0");
        agree(row, yours, root, new Ray(v(-2, 0.3, 0.3), v(1, 0, 0), 0, 2), "a row, a ray ending exactly at square #0 (open segment)");
        agree(row, yours, root, new Ray(v(-2, 0.3, 0.3), v(1, 0, 0), 0, Math.nextUp(2.0)), "a row, a ray ending just past square #0");
        agree(row, yours, root, new Ray(v(50, 1, 1), v(-1, 0, 0), 0, Double.POSITIVE_INFINITY), "a row, a ray along the squares' corners");
    }

    @Test
    public void aChainShapedTreeAThousandDeep() {
        Squares.Square[] row = new Squares.Square[1001];
        for (int i = 0; i < row.length; i++) {
            row[i] = new Squares.Square(i, 0, v(i, 0, 0), 1);
        }
        BvhTree tree = new BvhTree();
        tree.prepare(row, Squares.boxes(row));
        BvhNode node = BvhNode.leaf(tree.boxOf(1000, 1001), 1000, 1001);
        for (int k = 999; k >= 0; k--) {
            node = BvhNode.inner(tree.boxOf(k, 1001), BvhNode.leaf(tree.boxOf(k, k + 1), k, k + 1), node);
        }
        agree(row, tree, node, new Ray(v(2000, 0.2, 0.1), v(-1, 0, 0), 0, Double.POSITIVE_INFINITY), "a chain of 1,001 leaves");
        agree(row, tree, node, new Ray(v(-5, 0.2, 0.1), v(1, 0, 0), 0, Double.POSITIVE_INFINITY), "a chain of 1,001 leaves, from the other end");
    }

    @Test
    public void aSceneTenMillionUnitsAway() {
        Random random = new Random(78);
        Vec3 far = v(1e7, -1e7, 3e6);
        Squares.Square[] squares = Squares.random(random, 800, far, 3, 0.4);
        BvhTree yours = new BvhTree();
        BvhNode root = built(yours, squares, "800 squares around " + far);
        for (int i = 0; i < 600; i++) {
            agree(squares, yours, root, Squares.randomRay(random, far, 4), "800 squares around " + far);
        }
    }

    @Test
    public void slabHardCasesOnRandomIntegerBoxes() {
        Random random = new Random(79);
        BoundingBoxes boxes = new BoundingBoxes();
        for (int i = 0; i < 3000; i++) {
            Vec3 a = v(random.nextInt(7) - 3, random.nextInt(7) - 3, random.nextInt(7) - 3);
            Vec3 b = a.plus(v(random.nextInt(3), random.nextInt(3), random.nextInt(3)));
            Box box = new Box(a, b);
            Vec3 o = v(random.nextInt(9) - 4, random.nextInt(9) - 4, random.nextInt(9) - 4);
            Vec3 d = v(random.nextInt(3) - 1, random.nextInt(3) - 1, random.nextInt(3) - 1);
            if (d.lengthSquared() == 0) {
                continue;
            }
            Ray ray = new Ray(o, d, random.nextInt(3) == 0 ? 1 : 0, random.nextInt(3) == 0 ? 2 : Double.POSITIVE_INFINITY);
            boolean exact = ExactSlabs.hits(box, ray);
            boolean yours = boxes.hit(box, ray);
            if (exact) {
                assertTrue("hit(" + box + ", ray from " + o + " along " + d + ", [" + ray.start + ", " + ray.end + "]) returned false;"
                        + " the ray meets the box (faces, edges and corners count)", yours);
            } else {
                assertFalse("hit(" + box + ", ray from " + o + " along " + d + ", [" + ray.start + ", " + ray.end + "]) returned true;"
                        + " the ray passes the box by at least a unit", yours);
            }
        }
    }
}
