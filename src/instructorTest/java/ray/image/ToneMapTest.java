package ray.image;

import static org.junit.Assert.assertEquals;

import org.junit.Test;

/** ToneMap's exact bytes: exposure × L, clamp to [0, 1], gamma 1/2.2, floor(255·x + ½). */
public class ToneMapTest {

    @Test
    public void zeroIsBlackAndOneIsWhite() {
        assertEquals(0, ToneMap.toByte(0, 1));
        assertEquals(255, ToneMap.toByte(1, 1));
    }

    @Test
    public void valuesAboveOneClampToWhite() {
        assertEquals(255, ToneMap.toByte(1.0000001, 1));
        assertEquals(255, ToneMap.toByte(7.5, 1));
        assertEquals(255, ToneMap.toByte(Double.POSITIVE_INFINITY, 1));
    }

    @Test
    public void negativeAndNaNAreBlack() {
        assertEquals(0, ToneMap.toByte(-0.25, 1));
        assertEquals(0, ToneMap.toByte(-1e300, 1));
        assertEquals(0, ToneMap.toByte(Double.NEGATIVE_INFINITY, 1));
        assertEquals(0, ToneMap.toByte(Double.NaN, 1));
        assertEquals(0, ToneMap.toByte(0.5, Double.NaN));
    }

    @Test
    public void halfMapsTo186() {
        // 255·0.5^(1/2.2) = 255·0.729740 = 186.08, + 0.5, floor: 186
        assertEquals(186, ToneMap.toByte(0.5, 1));
    }

    @Test
    public void quarterMapsTo136() {
        // 255·0.25^(1/2.2) = 255·0.532520 = 135.79, + 0.5, floor: 136
        assertEquals(136, ToneMap.toByte(0.25, 1));
    }

    @Test
    public void exposureScalesRadianceBeforeTheCurve() {
        assertEquals(186, ToneMap.toByte(0.25, 2));
        assertEquals(ToneMap.toByte(0.5, 1), ToneMap.toByte(0.25, 2));
        assertEquals(255, ToneMap.toByte(0.6, 2));
        assertEquals(0, ToneMap.toByte(0.6, 0));
    }

    @Test
    public void everyByteRoundTripsThroughItsLinearValue() {
        // (k/255)^2.2 is the linear value that the curve maps to exactly k; rounding to nearest gives k back.
        for (int k = 0; k <= 255; k++) {
            assertEquals("byte " + k, k, ToneMap.toByte(Math.pow(k / 255.0, 2.2), 1));
        }
    }

    @Test
    public void roundsHalfUpAtTheBoundaryBetween127And128() {
        // 255·x^(1/2.2) = 127.5 exactly at x = (127.5/255)^2.2 = 0.5^2.2 = 0.2176376...; near there
        // the pre-rounding value changes by ≈ 266 per unit of x, so ±1e-9 relative moves it ≈ ±6e-8.
        double boundary = Math.pow(0.5, 2.2);
        assertEquals(127, ToneMap.toByte(boundary * (1 - 1e-9), 1));
        assertEquals(128, ToneMap.toByte(boundary * (1 + 1e-9), 1));
    }

    @Test
    public void roundsToNearestNotDownNearBlack() {
        // Byte 1 starts where 255·x^(1/2.2) = 0.5, at x = (0.5/255)^2.2 ≈ 1.105e-6; truncation would
        // give 0 up to (1/255)^2.2 ≈ 5.1e-6.
        double boundary = Math.pow(0.5 / 255, 2.2);
        assertEquals(0, ToneMap.toByte(boundary * (1 - 1e-6), 1));
        assertEquals(1, ToneMap.toByte(boundary * (1 + 1e-6), 1));
        assertEquals(1, ToneMap.toByte(3e-6, 1));
    }
}
