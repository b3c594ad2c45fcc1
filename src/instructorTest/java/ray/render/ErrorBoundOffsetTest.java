package ray.render;

import static org.junit.Assert.assertEquals;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.math.Vec3;
import ray.surface.HitGeometry;
import ray.surface.Sphere;
import ray.surface.Triangle;

/**
 * pbrt-v4's error-bound offset ({@link RayOffsets#ERROR_BOUND}): the bound on a re-projected hit's
 * error per coordinate ({@link HitGeometry#error}), hand-computed for a sphere, a triangle and a
 * translation, and the new ray's origin |n|·error along the normal, rounded one double further.
 * Records are filled by hand, so no student code runs.
 */
public class ErrorBoundOffsetTest {
    private static final double EPS = 0x1p-53;

    private static double gamma(int n) {
        return n * EPS / (1 - n * EPS);
    }

    private static IntersectionRecord hit(Vec3 location, Vec3 normal) {
        IntersectionRecord hit = new IntersectionRecord();
        hit.t = 1;
        hit.location = location;
        hit.normal = normal;
        return hit;
    }

    @Test
    public void gammaIsTheRelativeErrorOfNRoundedOperations() {
        assertEquals(3 * EPS / (1 - 3 * EPS), HitGeometry.gamma(3), 0);
    }

    @Test
    public void aSpheresPointErrsRadiallyByGamma6TimesItsRadiusPlusOneRounding() {
        // The top of a sphere of radius 2 at the origin: û = (0, 0, 1), point (0, 0, 2).
        HitGeometry g = new Sphere(Vec3.ZERO, 2).hitGeometry(hit(new Vec3(0, 0, 2), new Vec3(0, 0, 1)));
        assertEquals(new Vec3(0, 0, 2), g.point);
        assertEquals(0, g.error.x, 0);
        assertEquals(0, g.error.y, 0);
        assertEquals(gamma(6) * 2 + gamma(1) * 2, g.error.z, 0);
    }

    @Test
    public void aTrianglesPointErrsAlongItsNormalByItsThinnessAndTheHitsDistanceFromV0() {
        // The right triangle (0,0,0), (4,0,0), (0,4,0): thinness = 32/16 = 2; hit (1, 1, 0), |p − v0| = √2.
        Triangle triangle = new Triangle(new Vec3(0, 0, 0), new Vec3(4, 0, 0), new Vec3(0, 4, 0));
        HitGeometry g = triangle.hitGeometry(hit(new Vec3(1, 1, 0), new Vec3(0, 0, 1)));
        assertEquals(new Vec3(1, 1, 0), g.point);
        double offPlane = Math.sqrt(2) * (gamma(6) * 2 + gamma(4));
        assertEquals(gamma(2) * 1, g.error.x, 0);
        assertEquals(gamma(2) * 1, g.error.y, 0);
        assertEquals(offPlane, g.error.z, 0);
    }

    @Test
    public void aTranslationAddsTheRoundingOfItsSumAndCarriesTheErrorThrough() {
        // x ↦ x + (8, 0, 0) of the point (1, 2, 3) known within (1e-15, 0, 0): γ(3)·(|1| + |8|) + (1 + γ(3))·1e-15 in x.
        Vec3 error = Affine.translation(new Vec3(8, 0, 0)).pointError(new Vec3(1, 2, 3), new Vec3(1e-15, 0, 0));
        assertEquals(gamma(3) * 9 + (1 + gamma(3)) * 1e-15, error.x, 1e-30);
        assertEquals(gamma(3) * 2, error.y, 1e-30);
        assertEquals(gamma(3) * 3, error.z, 1e-30);
    }

    @Test
    public void newRaysStartTheBoundAlongTheNormalAndOneDoubleFurther() {
        HitGeometry g = new Sphere(Vec3.ZERO, 2).hitGeometry(hit(new Vec3(0, 0, 2), new Vec3(0, 0, 1)));
        double d = g.error.z;
        Ray out = RayOffsets.ERROR_BOUND.reflectionRay(g, new Vec3(0, 1, 1));
        assertEquals(new Vec3(0, 0, Math.nextUp(2 + d)), out.origin);
        Ray in = RayOffsets.ERROR_BOUND.reflectionRay(g, new Vec3(0, 1, -1));
        assertEquals(new Vec3(0, 0, Math.nextDown(2 - d)), in.origin);
        Ray shadow = RayOffsets.ERROR_BOUND.shadowRay(g, new Vec3(0, 0, 10));
        assertEquals(new Vec3(0, 0, Math.nextUp(2 + d)), shadow.origin);
        assertEquals(SecondaryRays.SHADOW_END, shadow.end, 0);
    }
}
