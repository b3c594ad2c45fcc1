package ray.shading;

import static org.junit.Assert.assertTrue;

import ray.math.Vec3;
import ray.testing.Hints;

/** Checks a BRDF's value f(l, v) for given unit vectors, each channel within a billionth of the value worked out by hand. */
final class BrdfValues {
    private BrdfValues() {
    }

    /**
     * Checks that {@code brdf.value(rhoD, n, l, v)} is {@code expected}, each channel within 1e-9 of it
     * relative to its size (the terms may be grouped and multiplied in any order).
     *
     * @param why the expected value worked out, shown where the hint level shows formulas
     */
    static void check(Brdf brdf, Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v, Vec3 expected, String why) {
        Vec3 result = brdf.value(rhoD, n, l, v);
        String message = brdf.getClass().getSimpleName() + ".value(ρd " + rhoD + ", n " + n + ", l " + l + ", v " + v + ") returned "
                + result + "; expected " + expected + Hints.fix(why.isEmpty() ? "" : " (" + why + ")");
        assertTrue(message, result != null);
        for (int axis = 0; axis < 3; axis++) {
            double e = expected.get(axis);
            assertTrue(message, Math.abs(result.get(axis) - e) <= 1e-9 * Math.max(1, Math.abs(e)));
        }
    }

    /**
     * The light a point sends back toward the eye from one light, as the 2019 shader computes it from
     * the BRDF: f(l, v) ⊙ I · max(0, n·l) / r², for the point {@code point} with normal {@code n}, seen
     * from {@code eye}, lit from {@code light} with intensity {@code intensity}.
     */
    static Vec3 reflected(Brdf brdf, Vec3 rhoD, Vec3 point, Vec3 n, Vec3 eye, Vec3 light, Vec3 intensity) {
        Vec3 toLight = light.minus(point);
        Vec3 l = toLight.normalized();
        Vec3 v = eye.minus(point).normalized();
        return brdf.value(rhoD, n, l, v).times(intensity).times(Math.max(0, n.dot(l)) / toLight.lengthSquared());
    }
}
