package ray.bvh;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Hints;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * The slab test (BoundingBoxes.hit): through, beside, behind and beyond the box; a ray that starts
 * inside; faces, edges and corners touched; flat boxes; directions with zero components, including
 * a ray in the plane of a face (where 0 · ∞ is NaN); and seeded random rays against the exact answer.
 */
@Points(1)
public class BoxHitTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Box UNIT = new Box(v(0, 0, 0), v(1, 1, 1));

    static void hit(Box box, Ray ray, boolean expected, String why) {
        boolean result = new BoundingBoxes().hit(box, ray);
        assertEquals("hit(" + box + ", ray from " + ray.origin + " along " + ray.direction + ", t in [" + ray.start + ", " + ray.end
                + "]) returned " + result + "; expected " + expected + Hints.fix(why), expected, result);
    }

    private static Ray ray(Vec3 origin, Vec3 direction) {
        return new Ray(origin, direction, 0, Double.POSITIVE_INFINITY);
    }

    @Test
    public void aRayThroughTheMiddleHitsAndOneBesideMisses() {
        hit(UNIT, ray(v(-1, 0.5, 0.5), v(1, 0.2, -0.1)), true, " (it crosses x = 0 at y 0.7, z 0.4)");
        hit(UNIT, ray(v(-1, 0.5, 0.5), v(1, 1, 0)), false, " (it leaves the slab 0 ≤ y ≤ 1 at t 0.5, before entering 0 ≤ x ≤ 1 at t 1)");
        hit(UNIT, ray(v(2, 3, 4), v(-1, -2, -3.5)), true, " (every component negative: swap each axis's distances)");
    }

    @Test
    public void onlyTheRaysSegmentCounts() {
        hit(UNIT, ray(v(2, 0.5, 0.5), v(1, 0, 0)), false, " (the box is behind the ray)");
        hit(UNIT, new Ray(v(-1, 0.5, 0.5), v(1, 0, 0), 0, 0.5), false, " (the ray ends at t 0.5, before the box at t 1)");
        hit(UNIT, new Ray(v(-1, 0.5, 0.5), v(1, 0, 0), 2.5, 10), false, " (the ray starts at t 2.5, past the box, which it leaves at t 2)");
        hit(UNIT, new Ray(v(-1, 0.5, 0.5), v(1, 0, 0), 0, 1.5), true, " (it ends at t 1.5, inside the box)");
    }

    @Test
    public void aRayThatStartsInsideHits() {
        hit(UNIT, ray(v(0.5, 0.5, 0.5), v(0, 0, 1)), true, " (the box's near distance is behind the origin: the interval starts at ray.start)");
        hit(UNIT, ray(v(0.25, 0.5, 0.75), v(-1, -2, 0.5)), true, " (inside, leaving through a face)");
    }

    @Test
    public void touchingAnEdgeOrACornerCounts() {
        hit(UNIT, ray(v(-1, 0, 0.5), v(1, 1, 0)), true, " (it meets the edge x = 0, y = 1 at t 1 and nothing else: near = far = 1)");
        hit(UNIT, ray(v(-1, -1, -1), v(1, 1, 1)), true, " (it enters at the corner (0, 0, 0))");
        hit(UNIT, ray(v(2, 2, 2), v(-1, -1, -1)), true, " (it enters at the corner (1, 1, 1))");
    }

    @Test
    public void aFlatBoxIsHit() {
        Box flat = new Box(v(0, 0, 0.5), v(1, 1, 0.5));
        hit(flat, ray(v(0.5, 0.5, 3), v(0, 0, -1)), true, " (the box of a triangle in the plane z = 0.5: it enters and leaves at the same t)");
        hit(flat, ray(v(-1, 0.3, 1.5), v(1, 0, -1)), true, " (slanting through the flat box)");
        hit(flat, ray(v(-1, 0.3, 3), v(1, 0, -1)), false, " (it crosses z = 0.5 at x 1.5, beside the flat box)");
    }

    @Test
    public void aRayParallelToAFaceIsJudgedByTheOtherAxes() {
        hit(UNIT, ray(v(-1, 0.5, 0.5), v(1, 0, 0)), true, " (d.y = d.z = 0: 1/d is ±infinity there, and the origin is between those planes)");
        hit(UNIT, ray(v(-1, 1.5, 0.5), v(1, 0, 0)), false, " (d.y = 0 and the origin is above y = 1: it never enters the y slab)");
        hit(UNIT, ray(v(0.5, -2, 0.5), v(0, 1, 0)), true, " (straight up the y axis)");
        hit(UNIT, ray(v(0.5, -2, 1.5), v(0, 1, 0)), false, " (straight up, beside the box)");
    }

    @Test
    public void aRayInThePlaneOfAFaceHits() {
        hit(UNIT, ray(v(-1, 1, 0.5), v(1, 0, 0)), true,
                " (d.y = 0 and the origin's y is the face's: (1 − 1) · (1/0) is 0 · ∞ = NaN; a comparison with NaN is false, so"
                        + " near = t0 > near ? t0 : near ignores it, where Math.max(near, NaN) would return NaN)");
        hit(UNIT, ray(v(0, -1, 0), v(0, 1, 0)), true, " (along the edge x = 0, z = 0: two NaN distances)");
        Box flat = new Box(v(0, 0, 0.5), v(1, 1, 0.5));
        hit(flat, ray(v(-1, 0.5, 0.5), v(1, 0, 0)), true, " (in the plane of a flat box: its z slab gives NaN at both planes)");
    }

    @Test
    public void aRayThatStartsOnAFlatBoxHitsIt() {
        Box flat = new Box(v(0, 0, 0.5), v(1, 1, 0.5));
        hit(flat, ray(v(0.5, 0.5, 0.5), v(0, 0, 1)), true,
                " (the box's interval is the single t = 0, the ray's own start: near = far, so the test is near ≤ far, not near < far)");
    }

    /** Rays whose distances need no rounding (small integers and halves) against boxes of the same: the exact answer, by rational arithmetic. */
    @Test
    public void randomRaysAgainstTheExactAnswer() {
        Random random = new Random(46201);
        for (int i = 0; i < 2000; i++) {
            Vec3 a = v(random.nextInt(9) - 4, random.nextInt(9) - 4, random.nextInt(9) - 4);
            Vec3 b = v(random.nextInt(9) - 4, random.nextInt(9) - 4, random.nextInt(9) - 4);
            Box box = new Box(v(Math.min(a.x, b.x), Math.min(a.y, b.y), Math.min(a.z, b.z)), v(Math.max(a.x, b.x), Math.max(a.y, b.y), Math.max(a.z, b.z)));
            Vec3 o = v((random.nextInt(17) - 8) / 2.0, (random.nextInt(17) - 8) / 2.0, (random.nextInt(17) - 8) / 2.0);
            Vec3 d = v(random.nextInt(5) - 2, random.nextInt(5) - 2, random.nextInt(5) - 2);
            if (d.lengthSquared() == 0) {
                continue;
            }
            double end = random.nextInt(4) == 0 ? random.nextInt(4) + 0.5 : Double.POSITIVE_INFINITY;
            Ray ray = new Ray(o, d, 0, end);
            hit(box, ray, ExactSlabs.hits(box, ray), " (the exact answer, by rational arithmetic)");
        }
    }
}
