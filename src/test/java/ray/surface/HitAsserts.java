package ray.surface;

import static org.junit.Assert.fail;
import static ray.surface.HitMessages.hitAt;
import static ray.surface.HitMessages.line;
import static ray.surface.HitMessages.returned;
import static ray.surface.HitMessages.returnedFalse;
import static ray.surface.HitMessages.returnedTrue;

import ray.IntersectionRecord;
import ray.Ray;

/**
 * The surface tests' checks of intersect's answer (hit or miss, t, β and γ), each failing with
 * {@link HitMessages}' wording: what was expected and what the student's intersect returned, plus
 * a {@link HitHints} cause when the numbers identify one. They judge exactly what JUnit's
 * assertTrue, assertFalse and assertEquals(expected, actual, tolerance) would; only the messages differ.
 * {@code what} names the ray and the surface, e.g. "the ray from (0,0,5) toward −z at the unit sphere".
 */
public final class HitAsserts {
    private HitAsserts() {
    }

    /** intersect must report a hit; the caller checks whatever it needs of it next. */
    public static void assertHit(String what, Surface surface, IntersectionRecord out, Ray ray) {
        IntersectionRecord before = Records.copyOf(out);
        if (!surface.intersect(out, ray)) {
            fail(line(what, "a hit", returnedFalse(), HitHints.forHitLeftInTheRecord(surface, ray, before, out)));
        }
    }

    /** intersect must report a hit at t (within tolerance). */
    public static void assertHitAt(String what, Surface surface, IntersectionRecord out, Ray ray, double t, double tolerance) {
        IntersectionRecord before = Records.copyOf(out);
        if (!surface.intersect(out, ray)) {
            fail(line(what, hitAt(t), returnedFalse(), HitHints.forHitLeftInTheRecord(surface, ray, before, out)));
        }
        assertT(what, surface, out, ray, t, tolerance);
    }

    /** The hit intersect already reported into {@code out} must be at t (within tolerance). */
    public static void assertT(String what, Surface surface, IntersectionRecord out, Ray ray, double t, double tolerance) {
        if (differ(t, out.t, tolerance)) {
            fail(line(what, hitAt(t), returned(out, surface instanceof TriangleSurface), HitHints.forWrongT(surface, ray, t, out.t)));
        }
    }

    /** intersect must report a hit at t (within tTolerance) with β and γ (each within bgTolerance). */
    public static void assertHitAt(String what, TriangleSurface triangle, IntersectionRecord out, Ray ray, double t, double tTolerance,
            double beta, double gamma, double bgTolerance) {
        String expected = hitAt(t, beta, gamma);
        if (!triangle.intersect(out, ray)) {
            fail(line(what, expected, returnedFalse(), null));
        }
        if (differ(t, out.t, tTolerance) || differ(beta, out.beta, bgTolerance) || differ(gamma, out.gamma, bgTolerance)) {
            String hint = differ(t, out.t, tTolerance) ? HitHints.forWrongT(triangle, ray, t, out.t) : null;
            fail(line(what, expected, returned(out, true), hint));
        }
    }

    /** The hit intersect already reported into {@code out} must have β and γ (each within tolerance); t is not judged. */
    public static void assertBarycentrics(String what, IntersectionRecord out, double beta, double gamma, double tolerance) {
        if (differ(beta, out.beta, tolerance) || differ(gamma, out.gamma, tolerance)) {
            fail(line(what, HitMessages.hitWith(beta, gamma), returned(out, true), null));
        }
    }

    /** intersect must report a miss (whether the record is left alone is Records.assertUntouched's to judge). */
    public static void assertMiss(String what, Surface surface, IntersectionRecord out, Ray ray) {
        if (surface.intersect(out, ray)) {
            fail(line(what, "a miss", returnedTrue(out, surface instanceof TriangleSurface), HitHints.forUnexpectedHit(surface, ray, out)));
        }
    }

    /**
     * intersect must report a miss and leave the record exactly as it was; when it wrote into the
     * record, the message says what it wrote and, when the numbers show it, why.
     */
    public static void assertMissUntouched(String what, Surface surface, IntersectionRecord out, Ray ray) {
        IntersectionRecord before = Records.copyOf(out);
        assertMiss(what, surface, out, ray);
        String hint = HitHints.forHitLeftInTheRecord(surface, ray, before, out);
        if (hint != null) {
            fail(line(what, "a miss that leaves the record alone", returnedFalse(), hint));
        }
        Records.assertUntouched(before, out);
    }

    /** JUnit's rule for assertEquals on doubles: equal (NaN equals NaN), or within the tolerance. */
    private static boolean differ(double expected, double actual, double tolerance) {
        return Double.compare(expected, actual) != 0 && !(Math.abs(expected - actual) <= tolerance);
    }
}
