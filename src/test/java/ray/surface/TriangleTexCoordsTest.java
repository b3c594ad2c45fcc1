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
 * Checks the texture coordinates Triangle.intersect reports: (u, v) = (1 − β − γ)·vt0 + β·vt1 +
 * γ·vt2, using the x and y of each vt (its third number is unused), and (0, 0) for a triangle
 * whose corners have none.
 */
@Points(1)
public class TriangleTexCoordsTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final double TOL = 1e-12;

    private static Triangle textured(Vec3 v0, Vec3 v1, Vec3 v2, Vec3 vt0, Vec3 vt1, Vec3 vt2) {
        Triangle triangle = new Triangle(v0, v1, v2);
        triangle.setVt0(vt0);
        triangle.setVt1(vt1);
        triangle.setVt2(vt2);
        return triangle;
    }

    private static void assertTexCoords(String what, Triangle triangle, Ray ray, double u, double v) {
        IntersectionRecord out = new IntersectionRecord();
        String described = what + " (the ray " + ray.origin + " + t·" + ray.direction + ")";
        HitAsserts.assertHit(described + " at the triangle", triangle, out, ray);
        // What intersect returned comes first, so that JUnit's "expected … but was …" follows the field it is about.
        String returned = described + ": " + HitMessages.returned(out, true) + "; ";
        String rule = ", with (u, v) = (1 − β − γ)·vt0 + β·vt1 + γ·vt2,";
        assertEquals(returned + "out.texU" + rule, u, out.texU, TOL);
        assertEquals(returned + "out.texV" + rule, v, out.texV, TOL);
    }

    @Test
    @Points(2)
    public void coordinatesBlendTheCornersByTheBarycentrics() {
        // v0 = origin, v1 = x, v2 = y: the point (x, y, 0) has β = x and γ = y.
        Triangle triangle = textured(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0), v(0.1, 0.2, 0), v(0.9, 0.3, 0), v(0.4, 0.8, 0));
        // β = 0.25, γ = 0.5, 1 − β − γ = 0.25: u = 0.025 + 0.225 + 0.2, v = 0.05 + 0.075 + 0.4.
        assertTexCoords("the point (0.25, 0.5, 0)", triangle, new Ray(v(0.25, 0.5, 1), v(0, 0, -1)), 0.45, 0.525);
        // β = 0.9, γ = 0.05: near v1, so near vt1.
        assertTexCoords("the point (0.9, 0.05, 0)", triangle, new Ray(v(0.9, 0.05, 1), v(0, 0, -1)), 0.835, 0.32);
        // β = 0.1, γ = 0.1: mostly vt0.
        assertTexCoords("the point (0.1, 0.1, 0)", triangle, new Ray(v(0.1, 0.1, 1), v(0, 0, -1)), 0.21, 0.27);
    }

    @Test
    public void aTiltedTriangleWithCoordinatesBeyondOne() {
        // v0 = (1,2,3), v1 = v0 + (2,0,1), v2 = v0 + (0,3,0): the point v0 + 0.2(2,0,1) + 0.3(0,3,0) = (1.4, 2.9, 3.2).
        // The face normal is (2,0,1) × (0,3,0) = (−3, 0, 6); the ray starts 0.5 of it away and comes
        // back along (0.75, 0, −1.5), so t = 2. vt1's u of 2 and the unused third numbers change nothing.
        Triangle triangle = textured(v(1, 2, 3), v(3, 2, 4), v(1, 5, 3), v(0, 0, 7), v(2, 0, 7), v(0, 1, 7));
        assertTexCoords("a tilted triangle at β = 0.2, γ = 0.3", triangle, new Ray(v(-0.1, 2.9, 6.2), v(0.75, 0, -1.5)), 0.4, 0.3);
    }

    @Test
    public void aTriangleWithoutTextureCoordinatesReportsZero() {
        // Records are reused from hit to hit: even one that held other coordinates must read (0, 0).
        Triangle plain = new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0));
        IntersectionRecord out = new IntersectionRecord();
        out.texU = 0.7;
        out.texV = 0.9;
        HitAsserts.assertHit("the ray from (0.25, 0.25, 1) toward −z at the triangle", plain, out, new Ray(v(0.25, 0.25, 1), v(0, 0, -1)));
        assertEquals("out.texU of a triangle whose vt are all (0, 0)", 0, out.texU, 0);
        assertEquals("out.texV of a triangle whose vt are all (0, 0)", 0, out.texV, 0);
    }
}
