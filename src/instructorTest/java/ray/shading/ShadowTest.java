package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Shadows as a shader sees them, through a FakeShadingContext: a blocked light adds nothing, and a light
 * that could add nothing anyway (behind a Lambertian surface) costs no shadow ray. Shadows in a
 * rendered scene, which need hits, are checked in the instructor's RenderedShadowTest.
 */
public class ShadowTest {
    private static final double TOL = 1e-12;

    private final IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, 1));
    private final Ray eyeRay = FakeShadingContext.rayFrom(v(0, 0, 5), Vec3.ZERO);

    @Test
    public void blockedLightAddsNothingWhileOtherLightsStillCount() {
        Vec3 blocked = v(0, 0, 2);
        FakeShadingContext shading = new FakeShadingContext()
                .light(blocked, v(4, 4, 4))
                .light(v(3, 0, 4), v(25, 25, 25));
        shading.lit = position -> !position.equals(blocked);
        Vec3 L = new Lambertian().shade(hit, eyeRay, shading, 0);
        // Only the second light: 25·0.8/25
        assertVec(v(0.8, 0.8, 0.8), L, TOL);
        assertEquals(2, shading.shadowRays);
    }

    @Test
    public void lightBehindLambertianCostsNoShadowRay() {
        FakeShadingContext shading = new FakeShadingContext()
                .light(v(0, 0, -2), v(4, 4, 4))
                .light(v(5, 5, -0.001), v(4, 4, 4));
        assertVec(Vec3.ZERO, new Lambertian().shade(hit, eyeRay, shading, 0), 0);
        assertEquals(0, shading.shadowRays);
    }

    /**
     * A black Lambertian is black. (Whether it costs shadow rays is the light loop's choice: the loop
     * is the students' code, and the solution tests only the cosine before its shadow test.)
     */
    @Test
    public void blackDiffuseColorIsBlack() {
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 2), v(4, 4, 4));
        assertVec(Vec3.ZERO, new Lambertian(Vec3.ZERO).shade(hit, eyeRay, shading, 0), 0);
    }
}
