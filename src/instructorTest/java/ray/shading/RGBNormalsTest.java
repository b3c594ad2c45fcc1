package ray.shading;

import static org.junit.Assert.assertEquals;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;
import ray.math.Vec3;

/** RGBNormals maps the unit normal to a color, (n + 1)/2 per channel, whatever the lights. */
public class RGBNormalsTest {
    private static final double TOL = 1e-15;

    private static Vec3 shadeNormal(Vec3 normal, FakeTracer tracer) {
        return new RGBNormals().shade(FakeTracer.hit(v(1, 2, 3), normal), FakeTracer.rayFrom(v(0, 0, 9), v(1, 2, 3)), tracer, 0);
    }

    @Test
    public void axisNormalsMapToHalfAndFullChannels() {
        FakeTracer tracer = new FakeTracer();
        assertVec(v(0.5, 0.5, 1), shadeNormal(v(0, 0, 1), tracer), TOL);
        assertVec(v(0, 0.5, 0.5), shadeNormal(v(-1, 0, 0), tracer), TOL);
        assertVec(v(0.5, 1, 0.5), shadeNormal(v(0, 1, 0), tracer), TOL);
    }

    @Test
    public void obliqueNormalMapsPerChannel() {
        // ((−0.6 + 1)/2, (0.8 + 1)/2, (0 + 1)/2)
        assertVec(v(0.2, 0.9, 0.5), shadeNormal(v(-0.6, 0.8, 0), new FakeTracer()), TOL);
    }

    @Test
    public void lightsAreIgnoredAndNoRaysAreTraced() {
        FakeTracer tracer = new FakeTracer().light(v(0, 0, 10), v(100, 100, 100));
        tracer.lit = position -> false;
        assertVec(v(0.5, 0.5, 1), shadeNormal(v(0, 0, 1), tracer), TOL);
        assertEquals(0, tracer.shadowRays);
        assertEquals(0, tracer.reflectionDirections.size());
    }
}
