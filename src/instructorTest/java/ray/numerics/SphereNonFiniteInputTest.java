package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.fail;

import java.lang.reflect.Field;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;
import ray.surface.Sphere;
import ray.surface.SphereSurface;

/**
 * NaN or infinite values in the ray (origin, direction, start, end) or the sphere (center, and the
 * radius, which setRadius rejects, so it is forced in by reflection as corrupt data would be): no
 * exception, a miss, the record untouched. Each case starts from a ray that does hit the unit sphere
 * (from (0, 0, 5) toward −z), so a miss is the bad value's doing.
 */
public class SphereNonFiniteInputTest {
    private static final double NAN = Double.NaN;
    private static final double INF = Double.POSITIVE_INFINITY;

    /** Each test first checks that, without a bad value, the same ray hits at t = 4 (else a "miss" proves nothing). */
    private static void assertBaseRayHits() {
        IntersectionRecord out = new IntersectionRecord();
        assertEquals("base ray", true, sphere(Vec3.ZERO, 1).intersect(out, new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1))));
        assertEquals(4, out.t, 1e-15);
    }

    @Test
    public void nonFiniteOriginMisses() {
        assertBaseRayHits();
        for (Vec3 origin : new Vec3[] {new Vec3(NAN, 0, 5), new Vec3(0, NAN, 5), new Vec3(0, 0, INF), new Vec3(-INF, 0, 5), new Vec3(INF, INF, INF)}) {
            assertMiss("origin " + origin, sphere(Vec3.ZERO, 1), new Ray(origin, new Vec3(0, 0, -1)));
        }
    }

    @Test
    public void nonFiniteDirectionMisses() {
        assertBaseRayHits();
        for (Vec3 direction : new Vec3[] {new Vec3(NAN, 0, -1), new Vec3(0, 0, NAN), new Vec3(0, 0, -INF), new Vec3(INF, 0, -1), new Vec3(-INF, -INF, -INF), new Vec3(0, 0, 0)}) {
            assertMiss("direction " + direction, sphere(Vec3.ZERO, 1), new Ray(new Vec3(0, 0, 5), direction));
        }
    }

    @Test
    public void nonFiniteRayStartOrEndMisses() {
        assertBaseRayHits();
        Vec3 origin = new Vec3(0, 0, 5);
        Vec3 direction = new Vec3(0, 0, -1);
        assertMiss("start NaN", sphere(Vec3.ZERO, 1), new Ray(origin, direction, NAN, INF));
        assertMiss("end NaN", sphere(Vec3.ZERO, 1), new Ray(origin, direction, 0, NAN));
        assertMiss("start +∞", sphere(Vec3.ZERO, 1), new Ray(origin, direction, INF, INF));
        assertMiss("end −∞", sphere(Vec3.ZERO, 1), new Ray(origin, direction, 0, -INF));
    }

    @Test
    public void nonFiniteCenterMisses() {
        assertBaseRayHits();
        for (Vec3 center : new Vec3[] {new Vec3(NAN, 0, 0), new Vec3(0, 0, NAN), new Vec3(0, 0, -INF), new Vec3(INF, 0, 0)}) {
            assertMiss("center " + center, sphere(center, 1), new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1)));
        }
    }

    @Test
    public void nonFiniteRadiusMisses() {
        assertBaseRayHits();
        for (double radius : new double[] {NAN, INF}) {
            assertMiss("radius " + radius, sphere(Vec3.ZERO, radius), new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1)));
        }
    }

    @Test
    public void setRadiusRejectsNonFiniteValues() {
        // Why the radius tests go around the setter: scene data cannot set these through it.
        for (double radius : new double[] {NAN, INF, -INF}) {
            try {
                new Sphere().setRadius(radius);
                fail("setRadius accepted " + radius);
            } catch (IllegalArgumentException expected) {
                // the loader reports it as a scene error
            }
        }
    }

    private static void assertMiss(String what, Sphere sphere, Ray ray) {
        IntersectionRecord out = new IntersectionRecord();
        boolean hit;
        try {
            hit = sphere.intersect(out, ray);
        } catch (RuntimeException e) {
            throw new AssertionError(what + ": intersect threw " + e, e);
        }
        assertFalse(what + ": reported a hit " + out, hit);
        assertEquals(what + ": t untouched", INF, out.t, 0);
        assertNull(what + ": location untouched", out.location);
        assertNull(what + ": normal untouched", out.normal);
        assertNull(what + ": surface untouched", out.surface);
    }

    /** A sphere with any center and radius; the radius goes into the private field, past setRadius. */
    private static Sphere sphere(Vec3 center, double radius) {
        Sphere sphere = new Sphere();
        sphere.setCenter(center);
        try {
            Field field = SphereSurface.class.getDeclaredField("radius");
            field.setAccessible(true);
            field.setDouble(sphere, radius);
        } catch (ReflectiveOperationException e) {
            throw new AssertionError("Sphere has no double field `radius` to force a bad value into", e);
        }
        return sphere;
    }
}
