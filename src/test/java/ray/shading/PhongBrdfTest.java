package ray.shading;

import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Rule;
import org.junit.Test;
import ray.math.Vec3;
import ray.testing.Points;
import ray.testing.StudentTaskRule;

/**
 * Checks PhongBrdf.value, the course's 2019 f = ρd/π + ks · max(0, n·h)^p with h = normalize(l + v),
 * with values worked out in each comment, and the course's own check values of lit points. The
 * exponents are whole numbers, so that Math.pow and a loop of products are equally right.
 */
@Points(1)
public class PhongBrdfTest {
    @Rule
    public final StudentTaskRule task = StudentTaskRule.of(getClass());

    private static final Vec3 UP = v(0, 0, 1);

    /** Light and eye along the normal: h = n, so f = ρd/π + ks. */
    @Test
    @Points(2)
    public void lightAndEyeAlongTheNormal() {
        Vec3 rhoD = v(0.5, 0.25, 1);
        Vec3 ks = v(1, 0.5, 0.25);
        BrdfValues.check(new PhongBrdf(ks, 10), rhoD, UP, UP, UP, rhoD.times(1 / Math.PI).plus(ks), "ρd/π + ks · 1^p");
    }

    /** Eye along n, light along (0.6, 0, 0.8): h = normalize(0.6, 0, 1.8), n·h = 3/√10, so with p = 2 the highlight is 0.9 ks. */
    @Test
    @Points(2)
    public void theHighlightUsesTheHalfVector() {
        BrdfValues.check(new PhongBrdf(v(1, 0.5, 0.25), 2), Vec3.ZERO, UP, v(0.6, 0, 0.8), UP, v(0.9, 0.45, 0.225),
                "ks · (n·h)², with n·h = 3/√10 from h = normalize(l + v)");
    }

    /** The same directions with p = 200: (n·h)^200 = 0.9^100. */
    @Test
    public void aLargeExponent() {
        double highlight = Math.pow(0.9, 100);
        BrdfValues.check(new PhongBrdf(v(1, 1, 1), 200), Vec3.ZERO, UP, v(0.6, 0, 0.8), UP, v(highlight, highlight, highlight),
                "(n·h)^200 = 0.9^100");
    }

    /**
     * f has no cosine in it: light and eye mirror each other at n·l = 0.6, so h = n and the highlight is
     * ks whole (the shader, not f, multiplies by n·l).
     */
    @Test
    @Points(2)
    public void fHasNoCosineInIt() {
        Vec3 rhoD = v(0.2, 0.2, 0.2);
        BrdfValues.check(new PhongBrdf(v(0.5, 0.5, 0.5), 7), rhoD, UP, v(0.8, 0, 0.6), v(-0.8, 0, 0.6),
                rhoD.times(1 / Math.PI).plus(v(0.5, 0.5, 0.5)), "h = n, so ρd/π + ks, neither divided nor multiplied by n·l");
    }

    /** A half vector below the surface: n·h < 0 gives no highlight, even with an odd exponent (never a negative one). */
    @Test
    public void noHighlightBelowTheSurface() {
        Vec3 rhoD = v(0.3, 0.6, 0.9);
        BrdfValues.check(new PhongBrdf(v(1, 1, 1), 3), rhoD, UP, v(0.6, 0, -0.8), v(0, 0.6, -0.8), rhoD.times(1 / Math.PI),
                "max(0, n·h)^p with n·h < 0 is 0: only ρd/π is left");
    }

    /**
     * The course's own checks: the point (0, 1, 0) with normal +y, seen from (0, 2, 0), ρd = (0, 0.5, 0.5),
     * ks = 1 and p = 1, lit by one light of intensity 100: at (5, 5, 5) it sends back
     * (0.64441663, 0.7631477, 0.7631477), at (1, 5, 1) (5.162396, 5.996022, 5.996022); both are
     * f ⊙ I · (n·l)/r², given to the course's seven or eight digits.
     */
    @Test
    @Points(2)
    public void theCoursesLitPoints() {
        Vec3 rhoD = v(0, 0.5, 0.5);
        Vec3 point = v(0, 1, 0);
        Vec3 eye = v(0, 2, 0);
        Vec3 intensity = v(100, 100, 100);
        PhongBrdf brdf = new PhongBrdf(v(1, 1, 1), 1);
        assertVec("the light at (5, 5, 5): f ⊙ I · (n·l)/r² with f = PhongBrdf.value", v(0.64441663, 0.7631477, 0.7631477),
                BrdfValues.reflected(brdf, rhoD, point, v(0, 1, 0), eye, v(5, 5, 5), intensity), 1e-7);
        assertVec("the light at (1, 5, 1): f ⊙ I · (n·l)/r² with f = PhongBrdf.value", v(5.162396, 5.996022, 5.996022),
                BrdfValues.reflected(brdf, rhoD, point, v(0, 1, 0), eye, v(1, 5, 1), intensity), 1e-6);
    }
}
