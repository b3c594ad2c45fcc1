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
import ray.testing.StudentTaskRule;

/** The box of a capped cylinder standing on its bottom cap (extra credit): hand-computed, moved, and seeded random ones. */
public class CylinderBoxBonusTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static void cylinder(Vec3 center, double radius, double height, Vec3 min, Vec3 max, String why) {
        Box box = new BoundingBoxes().ofCylinder(center, radius, height);
        String call = "ofCylinder(" + center + ", radius " + radius + ", height " + height + ")";
        assertNotNull(call + " returned null; expected a box", box);
        assertEquals(call + " returned " + box + "; expected the box from " + min + " to " + max + Hints.fix(why), new Box(min, max), box);
    }

    @Test
    @Points(value = 1, bonus = true)
    public void aCylinderReachesItsRadiusAcrossAndItsHeightUp() {
        cylinder(v(0, 0, 0), 1, 2, v(-1, 0, -1), v(1, 2, 1), " (x and z: center ∓ r; y: from the bottom cap up by the height)");
        cylinder(v(3, -2, 5), 0.5, 4, v(2.5, -2, 4.5), v(3.5, 2, 5.5), " (the bottom cap is at the center's y, not below it)");
    }

    @Test
    @Points(value = 1, bonus = true)
    public void randomCylinders() {
        Random random = new Random(4621);
        for (int i = 0; i < 200; i++) {
            Vec3 c = v(2000 * random.nextDouble() - 1000, 2000 * random.nextDouble() - 1000, 2000 * random.nextDouble() - 1000);
            double r = Math.exp(8 * random.nextDouble() - 4);
            double h = Math.exp(8 * random.nextDouble() - 4);
            cylinder(c, r, h, v(c.x - r, c.y, c.z - r), v(c.x + r, c.y + h, c.z + r), "");
        }
    }
}
