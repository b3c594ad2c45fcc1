package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * The solution's Lambertian shading, L = Σ kd ⊙ I · max(0, n·l) / r², against hand-computed values
 * (instructor-only: the students' own tests are ray.shading.LambertianTest and the hidden ones).
 */
public class LambertianSolutionTest {
    private static final double TOL = 1e-12;

    private final IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, 1));
    private final Ray eyeRay = FakeShadingContext.rayFrom(v(0, 0, 5), Vec3.ZERO);

    @Test
    public void lightStraightAboveGivesKdTimesIntensityOverDistanceSquared() {
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 2), v(4, 8, 12));
        Vec3 L = new Lambertian(v(0.5, 0.25, 1)).shade(hit, eyeRay, shading, 0);
        // n·l = 1, r² = 4: (0.5·4, 0.25·8, 1·12)/4
        assertVec(v(0.5, 0.5, 3), L, TOL);
        assertEquals("one shadow ray per contributing light", 1, shading.shadowRays);
    }

    @Test
    public void obliqueLightIsScaledByCosine() {
        FakeShadingContext shading = new FakeShadingContext().light(v(3, 0, 4), v(25, 50, 100));
        Vec3 L = new Lambertian(v(1, 0.5, 0.2)).shade(hit, eyeRay, shading, 0);
        // r = 5, n·l = 4/5: (1·25, 0.5·50, 0.2·100)·0.8/25
        assertVec(v(0.8, 0.8, 0.64), L, TOL);
    }

    @Test
    public void lightBehindTheSurfaceGivesZero() {
        FakeShadingContext shading = new FakeShadingContext().light(v(1, 2, -3), v(100, 100, 100));
        Vec3 L = new Lambertian(v(1, 1, 1)).shade(hit, eyeRay, shading, 0);
        assertVec(Vec3.ZERO, L, 0);
    }

    @Test
    public void lightInThePlaneOfTheSurfaceGivesZero() {
        FakeShadingContext shading = new FakeShadingContext().light(v(2, 0, 0), v(100, 100, 100));
        assertVec(Vec3.ZERO, new Lambertian().shade(hit, eyeRay, shading, 0), 0);
    }

    @Test
    public void twoLightsAdd() {
        FakeShadingContext shading = new FakeShadingContext()
                .light(v(0, 0, 2), v(4, 8, 12))
                .light(v(3, 0, 4), v(25, 50, 100));
        Vec3 L = new Lambertian(v(0.5, 0.25, 1)).shade(hit, eyeRay, shading, 0);
        // (0.5, 0.5, 3) from the first light + (0.5·25, 0.25·50, 1·100)·0.8/25 = (0.4, 0.4, 3.2)
        assertVec(v(0.9, 0.9, 6.2), L, TOL);
        assertEquals(2, shading.shadowRays);
    }

    @Test
    public void viewDirectionDoesNotMatter() {
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 2), v(4, 4, 4));
        Ray grazing = FakeShadingContext.rayFrom(v(-10, 3, 0.5), Vec3.ZERO);
        assertVec(v(1, 1, 1), new Lambertian().shade(hit, grazing, shading, 0), TOL);
    }

    @Test
    public void hitAwayFromOriginUsesVectorFromHitToLight() {
        // Hit at (1, 1, 1) with normal +x; light at (4, 1, 5): l = (3, 0, 4)/5, n·l = 0.6, r² = 25.
        IntersectionRecord sideHit = FakeShadingContext.hit(v(1, 1, 1), v(1, 0, 0));
        FakeShadingContext shading = new FakeShadingContext().light(v(4, 1, 5), v(50, 50, 50));
        Vec3 L = new Lambertian(v(1, 0.5, 0)).shade(sideHit, FakeShadingContext.rayFrom(v(5, 1, 1), v(1, 1, 1)), shading, 0);
        // 50·0.6/25 = 1.2 per unit of kd
        assertVec(v(1.2, 0.6, 0), L, TOL);
    }
}
