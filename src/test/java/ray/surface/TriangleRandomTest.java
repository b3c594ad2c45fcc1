package ray.surface;

import static org.junit.Assert.assertSame;
import static ray.surface.HitAsserts.assertHit;
import static ray.surface.HitAsserts.assertT;
import static ray.testing.Asserts.assertVec;
import static ray.testing.RandomVectors.randomVec;

import java.util.Random;
import org.junit.Rule;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Property test of Triangle.intersect on seeded random triangles and rays aimed at random interior
 * points: every ray hits, the barycentrics reproduce the location, and the location lies on the ray.
 */
@Points(2)
public class TriangleRandomTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    @Test
    public void barycentricsReproduceTheLocation() {
        Random random = new Random(31337);
        for (int i = 0; i < 1000; i++) {
            Vec3 v0 = randomVec(random, 10);
            Vec3 v1 = randomVec(random, 10);
            Vec3 v2 = randomVec(random, 10);
            Triangle triangle = new Triangle(v0, v1, v2);
            // An interior point away from the edges, so rounding cannot push it outside.
            double beta = 0.01 + 0.98 * random.nextDouble();
            double gamma = (0.99 - beta) * random.nextDouble() + 0.005;
            Vec3 target = v0.times(1 - beta - gamma).plus(v1.times(beta)).plus(v2.times(gamma));
            Vec3 origin = randomVec(random, 20);
            double scale = 0.5 + 2 * random.nextDouble();
            Ray ray = new Ray(origin, target.minus(origin).times(scale));
            // Skip rays that graze the triangle's plane: their hit point is ill-conditioned.
            Vec3 unitDir = ray.direction.normalized();
            if (Math.abs(unitDir.dot(triangle.getFaceNormal())) < 0.05) {
                continue;
            }

            IntersectionRecord out = new IntersectionRecord();
            String what = "random ray " + i + ", " + ray + ", aimed at " + triangle + " with beta = " + beta
                    + ", gamma = " + gamma;
            assertHit(what, triangle, out, ray);
            assertSame(what + ": out.surface must be the triangle", triangle, out.surface);
            Vec3 fromBarycentrics = v0.times(1 - out.beta - out.gamma).plus(v1.times(out.beta)).plus(v2.times(out.gamma));
            assertVec(what + ": (1 − beta − gamma)·v0 + beta·v1 + gamma·v2 must be the location", fromBarycentrics,
                    out.location, 1e-10);
            assertVec(what + ": the location must be ray.pointAt(t)", ray.pointAt(out.t), out.location, 1e-10);
            // The ray was aimed at target with direction (target − origin)·scale, so t = 1/scale.
            assertT(what, triangle, out, ray, 1 / scale, 1e-9);
            assertVec(what + ": location", target, out.location, 1e-9);
            assertVec(what + ": the normal of a triangle without vertex normals is its face normal",
                    triangle.getFaceNormal(), out.normal, 1e-14);
        }
    }
}
