package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.math.Vec3;

/** RGBNormals maps the unit normal to a color, (n + 1)/2 per channel, whatever the lights. */
public class RGBNormalsTest {
    private static final double TOL = 1e-15;

    private static Vec3 shadeNormal(Vec3 normal, FakeShadingContext shading) {
        return new RGBNormals().shade(FakeShadingContext.hit(v(1, 2, 3), normal), FakeShadingContext.rayFrom(v(0, 0, 9), v(1, 2, 3)), shading, 0);
    }

    @Test
    public void axisNormalsMapToHalfAndFullChannels() {
        FakeShadingContext shading = new FakeShadingContext();
        assertVec(v(0.5, 0.5, 1), shadeNormal(v(0, 0, 1), shading), TOL);
        assertVec(v(0, 0.5, 0.5), shadeNormal(v(-1, 0, 0), shading), TOL);
        assertVec(v(0.5, 1, 0.5), shadeNormal(v(0, 1, 0), shading), TOL);
    }

    @Test
    public void obliqueNormalMapsPerChannel() {
        // ((−0.6 + 1)/2, (0.8 + 1)/2, (0 + 1)/2)
        assertVec(v(0.2, 0.9, 0.5), shadeNormal(v(-0.6, 0.8, 0), new FakeShadingContext()), TOL);
    }

    @Test
    public void lightsAreIgnoredAndNoRaysAreTraced() {
        FakeShadingContext shading = new FakeShadingContext().light(v(0, 0, 10), v(100, 100, 100));
        shading.lit = position -> false;
        assertVec(v(0.5, 0.5, 1), shadeNormal(v(0, 0, 1), shading), TOL);
        assertEquals(0, shading.shadowRays);
        assertEquals(0, shading.reflectionDirections.size());
    }
}
