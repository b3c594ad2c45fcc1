package ray.surface;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks the texture coordinates Sphere.intersect reports: with (x, y, z) the unit outward normal,
 * u = ½ + atan2(x, z)/2π and v = ½ + asin(y)/π. No hit is on the seam (the −z half-plane x = 0,
 * where u jumps from 1 to 0) or at a pole (where u is undefined), where equally correct code differs.
 */
@Points(1)
public class SphereTexCoordsTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final double TOL = 1e-9;

    private static void assertTexCoords(String what, Sphere sphere, Ray ray, double u, double v) {
        IntersectionRecord out = new IntersectionRecord();
        String described = what + " (" + sphere + ", the ray " + ray.origin + " + t·" + ray.direction + ")";
        HitAsserts.assertHit(described, sphere, out, ray);
        // What intersect returned comes first, so that JUnit's "expected … but was …" follows the field it is about.
        String returned = described + ": " + HitMessages.returned(out, false) + " with the normal " + out.normal + "; ";
        String rule = ", with u = ½ + atan2(x, z)/(2π), v = ½ + asin(y)/π of the unit normal (x, y, z),";
        assertEquals(returned + "out.texU" + rule, u, out.texU, TOL);
        assertEquals(returned + "out.texV" + rule, v, out.texV, TOL);
    }

    @Test
    @Points(2)
    public void theEquatorFromFourSides() {
        Sphere unit = new Sphere(Vec3.ZERO, 1);
        // (0,0,1): atan2(0, 1) = 0. (1,0,0): atan2(1, 0) = π/2, so u = ¾. (−1,0,0): u = ¼.
        assertTexCoords("the front (0,0,1)", unit, new Ray(v(0, 0, 5), v(0, 0, -1)), 0.5, 0.5);
        assertTexCoords("the east side (1,0,0)", unit, new Ray(v(5, 0, 0), v(-1, 0, 0)), 0.75, 0.5);
        assertTexCoords("the west side (−1,0,0)", unit, new Ray(v(-5, 0, 0), v(1, 0, 0)), 0.25, 0.5);
        // (√½, 0, √½): atan2 = π/4, u = ½ + ⅛.
        double h = Math.sqrt(0.5);
        assertTexCoords("the point (√½, 0, √½)", unit, new Ray(v(5 * h, 0, 5 * h), v(-h, 0, -h)), 0.625, 0.5);
    }

    @Test
    public void latitudeRisesTowardThePoleAtPlusY() {
        Sphere unit = new Sphere(Vec3.ZERO, 1);
        // (0, ½, √¾): asin(½) = π/6, v = ½ + ⅙. (0, −½, √¾): v = ½ − ⅙.
        assertTexCoords("30° north (0, ½, √¾)", unit, new Ray(v(0, 0.5, 5), v(0, 0, -1)), 0.5, 0.5 + 1 / 6.0);
        assertTexCoords("30° south (0, −½, √¾)", unit, new Ray(v(0, -0.5, 5), v(0, 0, -1)), 0.5, 0.5 - 1 / 6.0);
        // Straight down from above onto (0.6, 0.8, 0): asin(0.8)/π, atan2(0.6, 0) = π/2.
        assertTexCoords("(0.6, 0.8, 0) from above", unit, new Ray(v(0.6, 5, 0), v(0, -1, 0)), 0.75,
                0.5 + Math.asin(0.8) / Math.PI);
    }

    @Test
    @Points(2)
    public void theNormalNotTheHitPointGivesTheCoordinates() {
        // Center (2, −1, 3), radius 2: the hit center + 2·n with n = (0.48, 0.6, 0.64), reached from
        // center + 6n along −2.5n (an unnormalized direction), so t = 4/2.5.
        Vec3 center = v(2, -1, 3);
        Vec3 n = v(0.48, 0.6, 0.64);
        Sphere sphere = new Sphere(center, 2);
        assertTexCoords("an offset sphere of radius 2", sphere, new Ray(center.plus(n.times(6)), n.times(-2.5)),
                0.5 + Math.atan2(0.48, 0.64) / (2 * Math.PI), 0.5 + Math.asin(0.6) / Math.PI);
        // From the center outward to (−0.8, −0.6, 0)·2 + center: a hit from inside has the same outward-normal coordinates.
        Vec3 m = v(-0.8, -0.6, 0);
        assertTexCoords("the same sphere from inside", sphere, new Ray(center, m.times(0.1)),
                0.5 + Math.atan2(-0.8, 0) / (2 * Math.PI), 0.5 + Math.asin(-0.6) / Math.PI);
    }
}
