package ray.shading;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * Glazed: Schlick's R = R0 + (1 − R0)(1 − cos θ)^5, the blend L = R·L_mirror + (1 − R)·L_substrate,
 * the mirror direction it asks the shading for, and the recursion cap at {@link Glazed#MAX_DEPTH}.
 */
public class GlazedTest {
    private static final double TOL = 1e-12;

    private final IntersectionRecord hit = FakeShadingContext.hit(Vec3.ZERO, v(0, 0, 1));

    /** A glaze over RGBNormals, whose value at normal (0, 0, 1) is (0.5, 0.5, 1) and needs no lights. */
    private static Glazed glazeOverNormals() {
        Glazed g = new Glazed();
        g.setSubstrate(new RGBNormals());
        return g;
    }

    @Test
    public void reflectanceAtNormalIncidenceIsR0() {
        // n = 1.5: R0 = (0.5/2.5)² = 0.04
        Glazed g = new Glazed();
        assertEquals(0.04, g.reflectance(1), 1e-15);
        assertEquals("from the other side too", 0.04, g.reflectance(-1), 1e-15);
    }

    @Test
    public void reflectanceAtSixtyDegreesFollowsSchlick() {
        // cos θ = 0.5: 0.04 + 0.96·0.5^5 = 0.04 + 0.03
        assertEquals(0.07, new Glazed().reflectance(0.5), 1e-15);
    }

    @Test
    public void reflectanceApproachesOneAtGrazing() {
        Glazed g = new Glazed();
        assertEquals(1.0, g.reflectance(0), 1e-15);
        // 0.04 + 0.96·0.999^5 ≈ 0.99521
        assertEquals(0.04 + 0.96 * Math.pow(0.999, 5), g.reflectance(1e-3), 1e-12);
        double previous = g.reflectance(0);
        for (int k = 1; k <= 100; k++) {
            double r = g.reflectance(k / 100.0);
            assertTrue("R falls as the view turns toward the normal (cos θ = " + k / 100.0 + ")", r < previous);
            previous = r;
        }
    }

    @Test
    public void refractiveIndexSetsR0() {
        Glazed g = new Glazed();
        g.setRefractiveIndex(3);
        // ((3 − 1)/(3 + 1))² = 0.25
        assertEquals(0.25, g.reflectance(1), 1e-15);
    }

    @Test
    public void normalIncidenceBlendsMirrorAndSubstrate() {
        FakeShadingContext shading = new FakeShadingContext();
        shading.reflected = v(10, 20, 30);
        Ray ray = FakeShadingContext.rayFrom(v(0, 0, 4), Vec3.ZERO);
        Vec3 L = glazeOverNormals().shade(hit, ray, shading, 0);
        // 0.04·(10, 20, 30) + 0.96·(0.5, 0.5, 1) = (0.4 + 0.48, 0.8 + 0.48, 1.2 + 0.96)
        assertVec(v(0.88, 1.28, 2.16), L, TOL);
        assertEquals(1, shading.reflectionDirections.size());
        assertVec("mirror of a head-on view is straight back", v(0, 0, 1),
                shading.reflectionDirections.get(0).normalized(), TOL);
        assertEquals("the reflection ray is one level deeper", 1, (int) shading.reflectionDepths.get(0));
    }

    @Test
    public void obliqueViewReflectsAboutTheNormal() {
        FakeShadingContext shading = new FakeShadingContext();
        shading.reflected = v(1, 1, 1);
        // Arriving along (1, 0, −1): e = (−1, 0, 1)/√2, cos θ = 1/√2; mirror = 2(n·e)n − e = (1, 0, 1)/√2.
        Ray ray = new Ray(v(-2, 0, 2), v(1, 0, -1));
        Vec3 L = glazeOverNormals().shade(hit, ray, shading, 3);
        // R = 0.04 + 0.96·(1 − 1/√2)^5 = 0.042069273124372...
        double r = 0.042069273124372364;
        assertVec(v(r + (1 - r) * 0.5, r + (1 - r) * 0.5, r + (1 - r) * 1), L, TOL);
        assertVec(v(1, 0, 1).normalized(), shading.reflectionDirections.get(0).normalized(), TOL);
        assertEquals(4, (int) shading.reflectionDepths.get(0));
    }

    @Test
    public void atMaxDepthNoReflectionRayIsRequested() {
        FakeShadingContext shading = new FakeShadingContext();
        shading.reflected = v(10, 20, 30);
        Ray ray = FakeShadingContext.rayFrom(v(0, 0, 4), Vec3.ZERO);
        Vec3 L = glazeOverNormals().shade(hit, ray, shading, Glazed.MAX_DEPTH);
        assertEquals(0, shading.reflectionDirections.size());
        // The mirror term reflects black: only (1 − 0.04)·(0.5, 0.5, 1) is left.
        assertVec(v(0.48, 0.48, 0.96), L, TOL);
    }

    @Test
    public void oneBelowMaxDepthStillReflectsAtMaxDepth() {
        FakeShadingContext shading = new FakeShadingContext();
        glazeOverNormals().shade(hit, FakeShadingContext.rayFrom(v(0, 0, 4), Vec3.ZERO), shading, Glazed.MAX_DEPTH - 1);
        assertEquals(1, shading.reflectionDirections.size());
        assertEquals(Glazed.MAX_DEPTH, (int) shading.reflectionDepths.get(0));
    }

    @Test
    public void zeroReflectanceTracesNoRay() {
        // n = 1 gives R0 = 0, so a head-on view reflects nothing and needs no reflection ray.
        Glazed g = glazeOverNormals();
        g.setRefractiveIndex(1);
        FakeShadingContext shading = new FakeShadingContext();
        shading.reflected = v(10, 20, 30);
        assertVec(v(0.5, 0.5, 1), g.shade(hit, FakeShadingContext.rayFrom(v(0, 0, 4), Vec3.ZERO), shading, 0), TOL);
        assertEquals(0, shading.reflectionDirections.size());
    }

    @Test
    public void defaultSubstrateIsLitLambertian() {
        // White Lambertian under a light at distance 2 with I = 4: substrate = 1; R = 0.04, mirror black.
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 2), v(4, 4, 4));
        Vec3 L = new Glazed().shade(hit, FakeShadingContext.rayFrom(v(0, 0, 4), Vec3.ZERO), shading, 0);
        assertVec(v(0.96, 0.96, 0.96), L, TOL);
        assertEquals(1, shading.shadowRays);
    }
}
