package ray.shading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * The course's 2019 shading ({@link ReflectionShader}, made from a Lambertian or Phong by
 * {@link Shader#forCourse}) against values worked out by hand, and against the course's own unit-test
 * values for its Lambertian and Phong (a point at (0, 1, 0) with normal +y, seen from (0, 2, 0)).
 */
public class Course2019ShadingTest {
    private static final double TOL = 1e-12;

    private static Shader lambertian2019(Vec3 kd) {
        return new Lambertian(kd).forCourse(Course.Y2019);
    }

    private static Shader phong2019(Vec3 kd, Vec3 ks, double p) {
        Phong phong = new Phong();
        phong.setDiffuseColor(kd);
        phong.setSpecularColor(ks);
        phong.setExponent(p);
        return phong.forCourse(Course.Y2019);
    }

    // The course's own test point: p = (0, 1, 0), n = +y, the ray coming straight down from (0, 2, 0).
    private final IntersectionRecord coursePoint = FakeShadingContext.hit(v(0, 1, 0), v(0, 1, 0));
    private final Ray courseRay = new Ray(v(0, 2, 0), v(0, -1, 0));

    @Test
    public void aLambertianIsRhoOverPiTimesIrradiance() {
        FakeShadingContext one = new FakeShadingContext().light(v(5, 5, 5), v(100, 100, 100));
        Vec3 L = lambertian2019(v(0, 0.5, 0.5)).shade(coursePoint, courseRay, one, 0);
        // r² = 66, n·l = 4/√66: 0.5·100·(4/√66)/66 = 0.37300451811919, then /π (the course's value).
        assertVec(v(0, 0.37300451811919, 0.37300451811919).times(1 / Math.PI), L, 1e-13);
    }

    @Test
    public void lambertianLightsAddAndAShadowedLightAddsNothing() {
        FakeShadingContext three = new FakeShadingContext().light(v(5, 5, 5), v(100, 100, 100))
                .light(v(0, 5, 0), v(0, 30, 50)).light(v(0, 5, 0), v(0, 30, 50));
        Shader shader = lambertian2019(v(0, 0.5, 0.5));
        // Each (0, 5, 0) light: n·l = 1, r² = 16, so 0.5·(30, 50)/16 = (0.9375, 1.5625).
        assertVec(v(0, 2.24800451811919, 3.49800451811919).times(1 / Math.PI), shader.shade(coursePoint, courseRay, three, 0), 1e-13);
        three.lit = position -> !position.equals(v(5, 5, 5));
        assertVec(v(0, 1.875, 3.125).times(1 / Math.PI), shader.shade(coursePoint, courseRay, three, 0), 1e-13);
    }

    @Test
    public void theCoursesPhongValues() {
        Shader phong = phong2019(v(0, 0.5, 0.5), Vec3.ONE, 1);
        assertVec(v(0.64441663, 0.7631477, 0.7631477),
                phong.shade(coursePoint, courseRay, new FakeShadingContext().light(v(5, 5, 5), v(100, 100, 100)), 0), 1e-7);
        assertVec(v(5.162396, 5.996022, 5.996022),
                phong.shade(coursePoint, courseRay, new FakeShadingContext().light(v(1, 5, 1), v(100, 100, 100)), 0), 1e-6);
        FakeShadingContext three = new FakeShadingContext().light(v(-1, 5, 2), v(100, 100, 100))
                .light(v(1, 5, 1), v(0, 30, 50)).light(v(1, 5, 1), v(0, 30, 50));
        assertVec(v(4.022259, 8.2814045, 10.679813), phong.shade(coursePoint, courseRay, three, 0), 1e-6);
        three.lit = position -> !position.equals(v(1, 5, 1));
        assertVec(v(4.022259, 4.6837916, 4.6837916), phong.shade(coursePoint, courseRay, three, 0), 1e-6);
    }

    @Test
    public void phongsHighlightIsWeightedByTheCosineAndNotNormalised() {
        // n = v = +z at the origin, light at (0, 3, 4): r = 5, l = (0, 0.6, 0.8), n·l = 0.8,
        // l + v = (0, 0.6, 1.8), so (n·h)² = 1.8²/3.6 = 0.9 exactly, and p = 2 gives 0.9.
        IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, 1));
        Ray ray = new Ray(v(0, 0, 5), v(0, 0, -1));
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 3, 4), v(25, 25, 25));
        Vec3 L = phong2019(v(0.5, 0.5, 0.5), Vec3.ONE, 2).shade(hit, ray, shading, 0);
        // f = 0.5/π + 0.9, times I·n·l/r² = 25·0.8/25 = 0.8.
        double expected = (0.5 / Math.PI + 0.9) * 0.8;
        assertVec(v(expected, expected, expected), L, TOL);
    }

    @Test
    public void aHitSeenFromBehindItsNormalIsBlackAndCostsNothing() {
        IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, -1));
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 3), v(10, 10, 10));
        shading.reflected = Vec3.ONE;
        Phong phong = new Phong();
        phong.setMirrorCoefficient(v(0.5, 0.5, 0.5));
        Vec3 L = phong.forCourse(Course.Y2019).shade(hit, new Ray(v(0, 0, 5), v(0, 0, -1)), shading, 0);
        assertVec(Vec3.ZERO, L, 0);
        assertEquals("no shadow ray for a gated hit", 0, shading.shadowRays);
        assertTrue("no mirror ray for a gated hit", shading.reflectionDirections.isEmpty());
        // 2017 has no gate: the same hit, lit from the light's side, is not black.
        FakeShadingContext lit = new FakeShadingContext().light(v(0, 0, -3), v(9, 9, 9));
        assertVec(v(1, 1, 1), new Lambertian(Vec3.ONE).shade(hit, new Ray(v(0, 0, 5), v(0, 0, -1)), lit, 0), TOL);
    }

    @Test
    public void theMirrorRayIsWeightedBySchlickPerChannel() {
        // d = (1, −1, 0)/√2 meets n = +y: n·v = 1/√2, d_r = (1, 1, 0)/√2.
        IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 1, 0));
        Ray ray = new Ray(v(-1, 1, 0), v(2, -2, 0));
        FakeShadingContext shading = new FakeShadingContext();
        shading.reflected = v(1, 2, 3);
        Lambertian lambertian = new Lambertian(Vec3.ONE);
        lambertian.setMirrorCoefficient(v(0, 0.5, 1));
        Vec3 L = lambertian.forCourse(Course.Y2019).shade(hit, ray, shading, 3);
        double m5 = Math.pow(1 - 1 / Math.sqrt(2), 5);
        assertVec(v(m5 * 1, (0.5 + 0.5 * m5) * 2, 1 * 3), L, TOL);
        assertEquals(1, shading.reflectionDirections.size());
        assertVec(v(1, 1, 0).normalized(), shading.reflectionDirections.get(0).normalized(), TOL);
        assertEquals("the mirror ray is one deeper", Integer.valueOf(4), shading.reflectionDepths.get(0));
    }

    @Test
    public void aZeroMirrorCoefficientTracesNoMirrorRay() {
        FakeShadingContext shading = new FakeShadingContext();
        shading.reflected = Vec3.ONE;
        Vec3 L = lambertian2019(Vec3.ONE).shade(FakeShadingContext.hit(Vec3.ZERO, v(0, 1, 0)),
                new Ray(v(-1, 1, 0), v(1, -1, 0)), shading, 0);
        assertVec(Vec3.ZERO, L, 0);
        assertTrue(shading.reflectionDirections.isEmpty());
    }

    /**
     * The shader asks for each mirror ray one depth deeper and leaves the course's limit to the renderer
     * (whose context traces no ray past 12 hits: PathHitsTest renders it); a context that stops there
     * as the renderer's does sees 11 mirror rays after the camera ray's hit.
     */
    @Test
    public void aPathHasAtMostTwelveHits() {
        // Two facing perfect mirrors: every mirror ray hits the other one, until the depth limit.
        Lambertian mirror = new Lambertian(Vec3.ZERO);
        mirror.setMirrorCoefficient(Vec3.ONE);
        Shader shader = mirror.forCourse(Course.Y2019);
        int[] hits = {0};
        ShadingContext bouncing = new ShadingContext() {
            @Override
            public java.util.List<Light> lights() {
                return java.util.List.of();
            }

            @Override
            public boolean unoccluded(IntersectionRecord hit, Vec3 lightPosition) {
                return true;
            }

            @Override
            public Vec3 radiance(IntersectionRecord from, Vec3 direction, int depth) {
                if (depth >= Course.MAX_PATH_HITS_2019) {
                    return Vec3.ZERO; // as the renderer's context: this ray's hit would be the 13th
                }
                hits[0]++;
                IntersectionRecord next = FakeShadingContext.hit(v(0, 0, direction.z > 0 ? 1 : -1), v(0, 0, direction.z > 0 ? -1 : 1));
                return shader.shade(next, new Ray(from.location, direction), this, depth);
            }
        };
        Vec3 L = shader.shade(FakeShadingContext.hit(v(0, 0, -1), v(0, 0, 1)), new Ray(v(0, 0, 0.5), v(0, 0, -1)), bouncing, 0);
        assertEquals("11 mirror rays after the camera ray's hit: 12 hits in all", 11, hits[0]);
        assertVec(Vec3.ZERO, L, 0);
    }

    @Test
    public void lightsThatCannotAddCostNoShadowRay() {
        IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, 1));
        FakeShadingContext shading = new FakeShadingContext()
                .light(v(0, 0, -2), v(5, 5, 5)) // behind the surface
                .light(v(3, 0, 0), v(5, 5, 5)) // in its tangent plane: n·l = 0
                .light(v(0, 0, 2), v(4, 4, 4));
        Vec3 L = lambertian2019(Vec3.ONE).shade(hit, new Ray(v(0, 0, 5), v(0, 0, -1)), shading, 0);
        assertVec(v(1, 1, 1).times(1 / Math.PI), L, TOL);
        assertEquals(1, shading.shadowRays);
    }

    @Test
    public void aLightOnTheSurfaceOrOppositeTheViewerGivesNoNaN() {
        IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, 1));
        // A light at the hit point itself (r = 0) and one exactly opposite the viewer (l = −v: no half vector).
        FakeShadingContext shading = new FakeShadingContext().light(Vec3.ZERO, v(5, 5, 5)).light(v(0, 0, -1), v(5, 5, 5));
        Vec3 L = phong2019(Vec3.ONE, Vec3.ONE, 20).shade(hit, new Ray(v(0, 0, 5), v(0, 0, -1)), shading, 0);
        assertTrue("finite: " + L, L.isFinite());
        assertVec(Vec3.ZERO, L, 0);
    }

    @Test
    public void theDefaultsOf2019() {
        ReflectionShader lambertian = (ReflectionShader) new Lambertian().forCourse(Course.Y2019);
        assertVec(v(0.2, 0.2, 0.2), lambertian.getDiffuseColor(), 0);
        ReflectionShader phong = (ReflectionShader) new Phong().forCourse(Course.Y2019);
        assertVec(Vec3.ONE, phong.getDiffuseColor(), 0);
        assertVec(Vec3.ONE, phong.getSpecularColor(), 0);
        assertEquals(1.0, phong.getExponent(), 0);
        assertVec(Vec3.ZERO, phong.getMirrorCoefficient(), 0);
        Lambertian y2017 = new Lambertian();
        assertSame(y2017, y2017.forCourse(Course.Y2017));
        assertVec(Vec3.ONE, y2017.getDiffuseColor(), 0);
    }

    @Test
    public void effectsFollowTheShader() {
        assertEquals(java.util.EnumSet.of(Effect.LIGHTING, Effect.SHADOWS), lambertian2019(Vec3.ONE).effects());
        Phong phong = new Phong();
        phong.setMirrorCoefficient(v(0, 0, 0.1));
        assertEquals(java.util.EnumSet.of(Effect.LIGHTING, Effect.SHADOWS, Effect.SPECULAR, Effect.REFLECTION),
                phong.forCourse(Course.Y2019).effects());
    }

    @Test
    public void aMirrorCoefficientOutsideZeroToOneIsRefused() {
        IllegalArgumentException e = org.junit.Assert.assertThrows(IllegalArgumentException.class,
                () -> new Lambertian().setMirrorCoefficient(v(0.5, 1.5, 0)));
        assertTrue(e.getMessage(), e.getMessage().startsWith("mirrorCoefficient is ") && e.getMessage().endsWith("expected three numbers from 0 to 1"));
    }

    @Test
    public void courseYears() {
        assertSame(Course.Y2019, Course.of("2019"));
        assertSame(Course.Y2017, Course.of(" 2017 "));
        assertEquals("course 2018 is not one ray1 knows; expected 2017 or 2019",
                org.junit.Assert.assertThrows(IllegalArgumentException.class, () -> Course.of("2018")).getMessage());
    }
}
