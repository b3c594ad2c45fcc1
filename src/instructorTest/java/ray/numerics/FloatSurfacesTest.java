package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.v;

import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accuracy.Sweep;
import ray.accuracy.Sweeps;
import ray.math.Vec3;
import ray.shading.Lambertian;
import ray.surface.Group;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/** The float variants of the accuracy report: float answers where float is exact, float's errors where it is not. */
public class FloatSurfacesTest {
    @Test
    public void aSphereHitWithExactFloatNumbersIsExact() {
        Sphere sphere = new Sphere(v(0, 0, -5), 1);
        IntersectionRecord hit = new IntersectionRecord();
        assertTrue(new FloatSurfaces.FloatSphere(sphere).intersect(hit, new Ray(v(0, 0, 0), v(0, 0, -1))));
        assertEquals(4, hit.t, 0);
        assertEquals(v(0, 0, -4), hit.location);
        assertEquals(v(0, 0, 1), hit.normal);
        sphere.setShader(new Lambertian());
        assertSame("the hit's surface shades as the original sphere", sphere.getShader(), hit.surface.getShader());
        assertEquals("and measures its hits as the original does", sphere.hitGeometry(hit).toString(), hit.surface.hitGeometry(hit).toString());
    }

    @Test
    public void everyNumberAFloatSphereReportsIsAFloat() {
        Sphere sphere = new Sphere(v(0.1, 0.2, -3.3), 0.7);
        IntersectionRecord hit = new IntersectionRecord();
        assertTrue(new FloatSurfaces.FloatSphere(sphere).intersect(hit, new Ray(v(0.01, 0.02, 0), v(0.03, 0.05, -1))));
        for (double x : new double[] {hit.t, hit.location.x, hit.location.y, hit.location.z, hit.normal.x, hit.normal.y, hit.normal.z}) {
            assertEquals(x, (double) (float) x, 0);
        }
        IntersectionRecord exact = new IntersectionRecord();
        assertTrue(sphere.intersect(exact, new Ray(v(0.01, 0.02, 0), v(0.03, 0.05, -1))));
        assertEquals("t within float's precision of the double answer", exact.t, hit.t, 8 * 0x1p-24 * exact.t);
    }

    @Test
    public void aTinySphereFarFromTheOriginIsBlurredInFloat() {
        // Radius 1e-3 at y = 1e4 + 5e-4: float's spacing there is 2⁻¹⁰ ≈ 9.8e-4, the sphere's size,
        // so float moves the center and the rays by up to half a radius and the normals it reports
        // are far off. The same sphere near the origin is fine in float.
        assertTrue(largestNormalError(1e4) > 0.3);
        assertTrue(largestNormalError(0) < 1e-3);
    }

    /** The largest |n_float − n_double| over 19 rays along x across a 1e-3 sphere whose center has y = base + 5e-4. */
    private static double largestNormalError(double base) {
        Sphere sphere = new Sphere(v(5, base + 5e-4, 0), 1e-3);
        double largest = 0;
        for (int k = -4; k <= 14; k++) {
            Ray ray = new Ray(v(0, base + k * 1e-4, 0), v(1, 0, 0));
            IntersectionRecord exact = new IntersectionRecord();
            IntersectionRecord single = new IntersectionRecord();
            boolean hitDouble = sphere.intersect(exact, ray);
            boolean hitFloat = new FloatSurfaces.FloatSphere(sphere).intersect(single, ray);
            if (hitDouble != hitFloat) {
                return Double.POSITIVE_INFINITY;
            }
            if (hitDouble) {
                largest = Math.max(largest, exact.normal.minus(single.normal).length());
            }
        }
        return largest;
    }

    @Test
    public void aFloatTriangleAgreesWithTheWatertightTestToFloatPrecision() {
        Triangle triangle = new Triangle(v(-1, -1, -2), v(2, -1, -2.5), v(0, 1.5, -3));
        java.util.Random random = new java.util.Random(2026);
        int agreed = 0;
        for (int k = 0; k < 2000; k++) {
            Ray ray = new Ray(v(0, 0, 0), v(random.nextDouble() * 3 - 1.5, random.nextDouble() * 3 - 1.5, -2));
            IntersectionRecord exact = new IntersectionRecord();
            IntersectionRecord single = new IntersectionRecord();
            boolean hitDouble = triangle.intersect(exact, ray);
            boolean hitFloat = new FloatSurfaces.FloatTriangle(triangle).intersect(single, ray);
            if (hitDouble && hitFloat) {
                assertEquals(exact.t, single.t, 1e-6 * exact.t);
                assertEquals(triangle.toString(), single.surface.toString());
            }
            agreed += hitDouble == hitFloat ? 1 : 0;
        }
        assertTrue("only rays within float rounding of an edge may disagree: " + agreed, agreed >= 1990);
    }

    @Test
    public void theRewriteKeepsTheTreeAndReplacesEveryPrimitive() {
        Group group = new Group();
        group.addSurface(new Sphere(v(0, 0, 0), 1));
        group.addSurface(new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0)));
        Surface copy = FloatSurfaces.of(group);
        List<String> kinds = new ArrayList<>();
        copy.children().forEach(c -> kinds.add(c.getClass().getSimpleName()));
        assertEquals(List.of("FloatSphere", "FloatTriangle"), kinds);
        assertFalse(new FloatSurfaces.FloatTriangle(new Triangle(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0)))
                .intersect(new IntersectionRecord(), new Ray(v(5, 5, 1), new Vec3(0, 0, -1))));
    }

    @Test
    public void theInstructorsSweepsReachTheStudy() {
        List<String> names = new ArrayList<>();
        for (Sweep s : Sweeps.available(Sweeps.SAMPLES)) {
            names.add(s.name);
        }
        assertEquals(Sweeps.ALL, names);
    }
}
