package ray.hidden;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static ray.surface.HitAsserts.assertBarycentrics;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertHitAt;
import static ray.surface.HitAsserts.assertMiss;
import static ray.surface.Records.assertUntouched;
import static ray.surface.Records.copyOf;
import static ray.surface.Records.sentinel;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.HitMessages;
import ray.surface.Sphere;
import ray.surface.Triangle;
import ray.testing.Points;
import ray.testing.StudentTaskRule;
import ray.testing.Visibility;

/**
 * Hidden triangle cases: vertices hit exactly from behind, a tilted triangle along a very long
 * direction, a ray starting on the triangle (as shadow rays do), a record that already holds a
 * closer t, and a small triangle far from the origin.
 */
@Points(value = 1, visibility = Visibility.HIDDEN)
public class TriangleHiddenTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    /** (0,0,2), (4,0,2), (0,2,2) in the plane z = 2, normal +z: a point is (4β, 2γ, 2). */
    private final Triangle flat = new Triangle(v(0, 0, 2), v(4, 0, 2), v(0, 2, 2));
    private static final String FLAT = "the triangle (0,0,2), (4,0,2), (0,2,2)";

    @Test
    public void verticesHitExactlyFromBehind() {
        // From z = −1 toward +z, each vertex is 3 away; the normal stays +z (never flipped toward the ray).
        double[][] vertexBetaGamma = {{0, 0, 0, 0}, {4, 0, 1, 0}, {0, 2, 0, 1}};
        for (double[] c : vertexBetaGamma) {
            IntersectionRecord out = new IntersectionRecord();
            String ray = "the ray from (" + c[0] + ", " + c[1] + ", −1) toward +z";
            assertHitAt(ray + " at " + FLAT + ", from behind, exactly at a vertex", flat, out, new Ray(v(c[0], c[1], -1), v(0, 0, 1)),
                    3, 0, c[2], c[3], 0);
            assertVec(ray + ": location", v(c[0], c[1], 2), out.location, 0);
            assertVec(ray + ": normal (geometric, not flipped)", v(0, 0, 1), out.normal, 0);
        }
    }

    @Test
    public void tiltedTriangleAlongAVeryLongDirection() {
        // Plane x + y/2 + z/3 = 1 through (1,0,0), (0,2,0), (0,0,3). Along t·(1000,1000,1000):
        // 1000t·(1 + 1/2 + 1/3) = 1 → t = 6/11000, at (6/11, 6/11, 6/11) = (1 − β − γ)(1,0,0) + β(0,2,0) + γ(0,0,3),
        // so β = 3/11, γ = 2/11. Normal: (−1,2,0) × (−1,0,3) = (6,3,2), of length 7.
        Triangle tilted = new Triangle(v(1, 0, 0), v(0, 2, 0), v(0, 0, 3));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray t·(1000,1000,1000) from the origin";
        assertHitAt(ray + " at the triangle (1,0,0), (0,2,0), (0,0,3) (t = 6/11000, β = 3/11, γ = 2/11)", tilted, out,
                new Ray(Vec3.ZERO, v(1000, 1000, 1000)), 6.0 / 11000, 1e-17, 3.0 / 11, 2.0 / 11, 1e-14);
        assertVec(ray + ": location", v(6.0 / 11, 6.0 / 11, 6.0 / 11), out.location, 1e-14);
        assertVec(ray + ": normal", v(6.0 / 7, 3.0 / 7, 2.0 / 7), out.normal, 1e-14);
    }

    @Test
    public void rayStartingOnTheTriangleDoesNotHitItAtTZero() {
        IntersectionRecord out = sentinel(null);
        IntersectionRecord before = copyOf(out);
        assertMiss("the ray from (1,0.5,2), on " + FLAT + ", toward +z: its hit t = 0 is not in (0, ∞)", flat, out,
                new Ray(v(1, 0.5, 2), v(0, 0, 1)));
        assertMiss("the ray from (1,0.5,2), on " + FLAT + ", toward −z: its hit t = 0 is not in (0, ∞)", flat, out,
                new Ray(v(1, 0.5, 2), v(0, 0, -1)));
        assertUntouched(before, out);
        assertHitAt("the ray from (1,0.5,3) toward −z at " + FLAT, flat, out, new Ray(v(1, 0.5, 3), v(0, 0, -1)), 1, 0);
    }

    @Test
    public void hitReplacesARecordThatHoldsACloserT() {
        Sphere other = new Sphere();
        IntersectionRecord out = sentinel(other);
        out.t = 1;
        assertHitAt("the ray from (1,0.5,5) toward −z at " + FLAT + ", into a record whose t was 1 (a hit must replace out.t,"
                + " whatever it held: only ray.start and ray.end limit t)", flat, out, new Ray(v(1, 0.5, 5), v(0, 0, -1)), 3, 0);
        assertSame("a hit must set out.surface", flat, out.surface);
        assertBarycentrics("a hit must set out.beta and out.gamma", out, 0.25, 0.25, 1e-15);
    }

    @Test
    public void smallTriangleFarFromTheOrigin() {
        // Legs of 0.01 from v0 = (100, 200, 300); the ray 5 above v0 + (0.0025, 0.005) hits at β = 0.25, γ = 0.5.
        Vec3 v0 = v(100, 200, 300);
        Triangle small = new Triangle(v0, v0.plus(v(0.01, 0, 0)), v0.plus(v(0, 0.01, 0)));
        IntersectionRecord out = new IntersectionRecord();
        String ray = "the ray toward −z over the point (100.0025, 200.005, 300)";
        assertHitAt(ray + " at the triangle with legs 0.01 at (100,200,300)", small, out, new Ray(v0.plus(v(0.0025, 0.005, 5)),
                v(0, 0, -1)), 5, 1e-9, 0.25, 0.5, 1e-9);
        assertVec(ray + ": normal", v(0, 0, 1), out.normal, 1e-12);
        assertMiss("the ray toward −z over (100.011, 200.005, 300) passes beside the small triangle", small, new IntersectionRecord(),
                new Ray(v0.plus(v(0.011, 0.005, 5)), v(0, 0, -1)));
    }

    /**
     * Seeded: random triangles up to 10 from the origin with random texture coordinates in [−2, 3],
     * hit at random barycentrics (each at least 0.01); the reported (u, v) must be the blend
     * (1 − β − γ)·vt0 + β·vt1 + γ·vt2 at the β and γ the ray was aimed at.
     */
    @Test
    public void textureCoordinatesAreTheBarycentricBlend() {
        java.util.Random random = new java.util.Random(3_000_014);
        for (int k = 0; k < 300; k++) {
            Vec3[] corners = new Vec3[3];
            Vec3[] vts = new Vec3[3];
            for (int c = 0; c < 3; c++) {
                corners[c] = v(20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10, 20 * random.nextDouble() - 10);
                vts[c] = v(5 * random.nextDouble() - 2, 5 * random.nextDouble() - 2, 0);
            }
            Vec3 normal = corners[1].minus(corners[0]).cross(corners[2].minus(corners[0]));
            if (normal.length() < 1) {
                continue; // nearly degenerate: not what this test is about
            }
            double beta = 0.01 + 0.98 * random.nextDouble();
            double gamma = 0.01 + (0.98 - beta) * random.nextDouble();
            Vec3 point = corners[0].plus(corners[1].minus(corners[0]).times(beta)).plus(corners[2].minus(corners[0]).times(gamma));
            Vec3 unit = normal.normalized();
            Vec3 origin = point.plus(unit.times(1 + 4 * random.nextDouble()));
            Triangle triangle = new Triangle(corners[0], corners[1], corners[2]);
            triangle.setVt0(vts[0]);
            triangle.setVt1(vts[1]);
            triangle.setVt2(vts[2]);
            IntersectionRecord out = new IntersectionRecord();
            String what = "the triangle " + corners[0] + ", " + corners[1] + ", " + corners[2] + " with vt " + vts[0] + ", "
                    + vts[1] + ", " + vts[2] + " hit at β = " + beta + ", γ = " + gamma;
            assertHit(what, triangle, out, new Ray(origin, point.minus(origin)));
            double alpha = 1 - beta - gamma;
            String returned = what + ": " + HitMessages.returned(out, true) + "; ";
            assertEquals(returned + "out.texU", alpha * vts[0].x + beta * vts[1].x + gamma * vts[2].x, out.texU, 1e-8);
            assertEquals(returned + "out.texV", alpha * vts[0].y + beta * vts[1].y + gamma * vts[2].y, out.texV, 1e-8);
        }
    }
}
