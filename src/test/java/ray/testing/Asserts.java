package ray.testing;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import ray.math.Vec3;

/** Assertions shared by the tests. */
public final class Asserts {
    private Asserts() {
    }

    /** Each coordinate within {@code tolerance} of the expected one. */
    public static void assertVec(Vec3 expected, Vec3 actual, double tolerance) {
        assertVec("", expected, actual, tolerance);
    }

    public static void assertVec(String message, Vec3 expected, Vec3 actual, double tolerance) {
        String prefix = message.isEmpty() ? "" : message + ": ";
        assertTrue(prefix + "expected " + expected + " but was null", actual != null);
        assertEquals(prefix + "x of " + actual + " (expected " + expected + ")", expected.x, actual.x, tolerance);
        assertEquals(prefix + "y of " + actual + " (expected " + expected + ")", expected.y, actual.y, tolerance);
        assertEquals(prefix + "z of " + actual + " (expected " + expected + ")", expected.z, actual.z, tolerance);
    }

    public static Vec3 v(double x, double y, double z) {
        return new Vec3(x, y, z);
    }
}
