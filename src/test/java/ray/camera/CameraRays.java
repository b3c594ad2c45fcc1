package ray.camera;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static ray.testing.Asserts.assertVec;

import ray.Ray;
import ray.math.Vec3;

/** The check every camera test makes: the ray for one image point, compared with the one worked out by hand. */
public final class CameraRays {
    /** Rays are compared to this tolerance in each coordinate: a correct camera is off by rounding only. */
    public static final double TOL = 1e-14;

    private CameraRays() {
    }

    /**
     * The ray {@code camera.generateRay(u, v)} is this ray: the same origin (to rounding), a direction
     * along this one (any positive multiple is the same ray, so normalizing it or not is the
     * camera's choice) and the whole half-line t in (0, ∞).
     *
     * @param which names the camera in failure messages, e.g. "the default PerspectiveCamera"
     */
    public static void assertRay(String which, Camera camera, double u, double v, Vec3 origin, Vec3 direction) {
        assertRay(which, camera, u, v, origin, direction, TOL);
    }

    public static void assertRay(String which, Camera camera, double u, double v, Vec3 origin, Vec3 direction,
            double tolerance) {
        Ray ray = camera.generateRay(u, v);
        String what = which + ", image point (" + u + ", " + v + ")";
        assertNotNull(what + ": generateRay returned null", ray);
        assertVecNamingFloat(what + ": ray origin", origin, ray.origin, tolerance);
        assertNotNull(what + ": the ray's direction is null", ray.direction);
        double length = ray.direction.length();
        if (!(length > 0) || Double.isInfinite(length)) {
            throw new AssertionError(what + ": the ray's direction " + ray.direction + " has length " + length
                    + "; expected a direction along " + direction);
        }
        // Compared as unit vectors: d and αd (α > 0) are the same ray.
        assertVecNamingFloat(what + ": ray direction (compared as a unit vector; expected along " + direction + ", got "
                + ray.direction + ")", direction.normalized(), ray.direction.times(1 / length), tolerance);
        String segment = what + ": the ray must cover t in (0, ∞); new Ray(origin, direction) does";
        assertEquals(segment + " (ray.start)", 0.0, ray.start, 0);
        assertEquals(segment + " (ray.end)", Double.POSITIVE_INFINITY, ray.end, 0);
    }

    /**
     * assertVec, whose message also says "float precision" when the vector is off by about float's
     * rounding: a float keeps 24 bits, so a value that passed through one is off by up to 2⁻²⁴ ≈ 6e-8
     * of its size, where a double computation is off by 1e-16. An error between 1e-10 and 1e-6 of the
     * vector's size is that, and nothing else a camera does wrong (a wrong formula is off by far more).
     */
    private static void assertVecNamingFloat(String message, Vec3 expected, Vec3 actual, double tolerance) {
        double size = Math.max(1, Math.max(Math.abs(expected.x), Math.max(Math.abs(expected.y), Math.abs(expected.z))));
        double error = actual == null ? Double.NaN
                : Math.max(Math.abs(expected.x - actual.x), Math.max(Math.abs(expected.y - actual.y), Math.abs(expected.z - actual.z)));
        boolean floatSized = error > 1e-10 * size && error < 1e-6 * size;
        // The order of magnitude only: the same mistake written another way is off by another multiple of it.
        assertVec(floatSized ? message + " [off by some 1e" + Math.round(Math.log10(error)) + ", about float precision (7 digits, where"
                + " double keeps 16): does a float variable or a (float) cast hold a value on the way?]" : message,
                expected, actual, tolerance);
    }
}
