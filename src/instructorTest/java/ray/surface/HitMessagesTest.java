package ray.surface;

import static org.junit.Assert.assertEquals;

import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/** The wording of intersection failures, on hand-written records (no student code runs here). */
public class HitMessagesTest {
    /** The record of a hit at t (> 0) with β and γ, as the Group tests' stand-in surface reports one. */
    private static IntersectionRecord hit(double t, double beta, double gamma) {
        IntersectionRecord out = new IntersectionRecord();
        new FixedHitSurface("hand-made", t, Vec3.ZERO, beta, gamma).intersect(out, new Ray(Vec3.ZERO, new Vec3(0, 0, 1)));
        return out;
    }

    @Test
    public void aWrongTriangleHitShowsExpectedAndReturnedTBetaAndGamma() {
        assertEquals("the ray: expected a hit at t = 3 (β = 0.25, γ = 0.25); your intersect returned t = 3.5 (β = 0.5, γ = 0.75)",
                HitMessages.line("the ray", HitMessages.hitAt(3, 0.25, 0.25), HitMessages.returned(hit(3.5, 0.5, 0.75), true), null));
    }

    @Test
    public void aMissShowsFalseAndAnUnexpectedHitShowsItsValues() {
        assertEquals("r: expected a hit at t = 4; your intersect returned false",
                HitMessages.line("r", HitMessages.hitAt(4), HitMessages.returnedFalse(), null));
        assertEquals("r: expected a miss; your intersect returned true with t = 6; a hint",
                HitMessages.line("r", "a miss", HitMessages.returnedTrue(hit(6, 0.1, 0.2), false), "a hint"));
        assertEquals("your intersect returned true with t = 3 (β = 0.5, γ = 0.625)", HitMessages.returnedTrue(hit(3, 0.5, 0.625), true));
        assertEquals("a hit with β = 0.25, γ = 0.5", HitMessages.hitWith(0.25, 0.5));
    }

    @Test
    public void numbersAreWholeWhenWholeAndOtherwiseEveryDigit() {
        assertEquals("3", HitMessages.number(3.0));
        assertEquals("-2", HitMessages.number(-2.0));
        assertEquals("0", HitMessages.number(0.0));
        assertEquals("0.25", HitMessages.number(0.25));
        // 7 − √3: all 16 digits, so a result one ulp off reads differently.
        assertEquals("5.267949192431123", HitMessages.number(7 - Math.sqrt(3)));
        assertEquals("4.0E-6", HitMessages.number(4e-6));
        assertEquals("1.0E15", HitMessages.number(1e15));
        assertEquals("∞", HitMessages.number(Double.POSITIVE_INFINITY));
        assertEquals("-∞", HitMessages.number(Double.NEGATIVE_INFINITY));
        assertEquals("NaN", HitMessages.number(Double.NaN));
    }
}
