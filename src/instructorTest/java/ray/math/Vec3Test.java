package ray.math;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotEquals;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import org.junit.Test;

/** Checks each Vec3 operation on hand-computed values, and that vectors are immutable values. */
public class Vec3Test {
    private static final Vec3 A = v(1, 2, 3);
    private static final Vec3 B = v(-4, 0.5, 2);

    @Test
    public void plusAndMinusWorkPerCoordinate() {
        assertVec(v(-3, 2.5, 5), A.plus(B), 0);
        assertVec(v(5, 1.5, 1), A.minus(B), 0);
    }

    @Test
    public void timesScalarScalesEveryCoordinate() {
        assertVec(v(-2, -4, -6), A.times(-2), 0);
    }

    @Test
    public void timesVectorIsComponentWise() {
        // (1·−4, 2·0.5, 3·2)
        assertVec(v(-4, 1, 6), A.times(B), 0);
    }

    @Test
    public void plusScaledIsPointAlongARay() {
        // (1, 2, 3) + 2·(−4, 0.5, 2) = (−7, 3, 7)
        assertVec(v(-7, 3, 7), A.plusScaled(2, B), 0);
    }

    @Test
    public void negateFlipsEverySign() {
        assertVec(v(-1, -2, -3), A.negate(), 0);
    }

    @Test
    public void dotIsSumOfProducts() {
        // −4 + 1 + 6
        assertEquals(3.0, A.dot(B), 0);
    }

    @Test
    public void crossIsRightHandedAndAntiCommutative() {
        assertVec(v(0, 0, 1), v(1, 0, 0).cross(v(0, 1, 0)), 0);
        assertVec(v(1, 0, 0), v(0, 1, 0).cross(v(0, 0, 1)), 0);
        assertVec(v(0, 1, 0), v(0, 0, 1).cross(v(1, 0, 0)), 0);
        // (2·2 − 3·0.5, 3·−4 − 1·2, 1·0.5 − 2·−4) = (2.5, −14, 8.5)
        assertVec(v(2.5, -14, 8.5), A.cross(B), 0);
        assertVec(v(-2.5, 14, -8.5), B.cross(A), 0);
    }

    @Test
    public void crossIsPerpendicularToBothFactors() {
        Vec3 c = A.cross(B);
        assertEquals(0, c.dot(A), 0);
        assertEquals(0, c.dot(B), 0);
    }

    @Test
    public void lengthOfThreeFourTwelveIsThirteen() {
        Vec3 p = v(3, -4, 12);
        assertEquals(169, p.lengthSquared(), 0);
        assertEquals(13, p.length(), 0);
    }

    @Test
    public void normalizedHasUnitLengthAndSameDirection() {
        assertVec(v(0.6, 0, -0.8), v(3, 0, -4).normalized(), 1e-15);
        assertEquals(1, v(1e-150, 0, 0).normalized().length(), 0);
    }

    /** Below ~1e-154 the squared length underflows to 0, above ~1e154 it overflows: both must still normalize. */
    @Test
    public void normalizedSurvivesUnderflowAndOverflowOfTheSquaredLength() {
        assertVec(v(0.6, 0, -0.8), v(3e-200, 0, -4e-200).normalized(), 1e-15);
        assertVec(v(0.6, 0, -0.8), v(3e200, 0, -4e200).normalized(), 1e-15);
        assertVec(v(0, 1, 0), v(0, Double.MIN_VALUE, 0).normalized(), 0);
    }

    @Test
    public void normalizedOfZeroStaysZeroInsteadOfNaN() {
        Vec3 n = Vec3.ZERO.normalized();
        assertVec(Vec3.ZERO, n, 0);
        assertTrue(n.isFinite());
    }

    @Test
    public void maxAbsIsLargestAbsoluteCoordinate() {
        assertEquals(7, v(-7, 3, 5).maxAbs(), 0);
        assertEquals(5, v(1, -3, 5).maxAbs(), 0);
        assertEquals(4, v(1, -4, 2).maxAbs(), 0);
    }

    @Test
    public void getReturnsCoordinateByAxis() {
        assertEquals(1, A.get(0), 0);
        assertEquals(2, A.get(1), 0);
        assertEquals(3, A.get(2), 0);
    }

    @Test
    public void isFiniteRejectsNaNAndInfinity() {
        assertTrue(A.isFinite());
        assertFalse(v(Double.NaN, 0, 0).isFinite());
        assertFalse(v(0, Double.POSITIVE_INFINITY, 0).isFinite());
        assertFalse(v(0, 0, Double.NEGATIVE_INFINITY).isFinite());
    }

    @Test
    public void operationsLeaveTheOperandsUnchanged() {
        Vec3 a = v(1, 2, 3);
        a.plus(B);
        a.times(5);
        a.normalized();
        a.negate();
        assertVec(v(1, 2, 3), a, 0);
    }

    @Test
    public void equalsAndHashCodeCompareValues() {
        assertEquals(v(1, 2, 3), A);
        assertEquals(v(1, 2, 3).hashCode(), A.hashCode());
        assertNotEquals(v(9, 2, 3), A);
        assertNotEquals(v(1, 9, 3), A);
        assertNotEquals(v(1, 2, 9), A);
        // Permuted coordinates are a different vector (the hash must not be symmetric either).
        assertNotEquals(v(3, 2, 1), A);
        assertNotEquals(v(3, 2, 1).hashCode(), A.hashCode());
        assertNotEquals(A, "(1.0, 2.0, 3.0)");
        assertNotEquals(A, null);
    }

    @Test
    public void constantsAreZeroAndOne() {
        assertVec(v(0, 0, 0), Vec3.ZERO, 0);
        assertVec(v(1, 1, 1), Vec3.ONE, 0);
    }
}
