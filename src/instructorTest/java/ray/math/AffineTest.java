package ray.math;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static ray.testing.Asserts.assertVec;
import static ray.testing.Asserts.v;

import java.util.Random;
import org.junit.Test;

/**
 * Checks Affine: points get the translation and vectors do not, rotations by multiples of 90° are
 * exact, {@code after} composes in the documented order, and inverse and transpose are right
 * (on hand values and on seeded random transforms).
 */
public class AffineTest {
    @Test
    public void translationMovesPointsButNotVectors() {
        Affine t = Affine.translation(v(1, -2, 3));
        assertVec(v(5, 3, 9), t.applyToPoint(v(4, 5, 6)), 0);
        assertVec(v(4, 5, 6), t.applyToVector(v(4, 5, 6)), 0);
    }

    @Test
    public void scaleActsPerAxisOnPointsAndVectors() {
        Affine s = Affine.scale(v(2, 3, -1));
        assertVec(v(2, 6, -3), s.applyToPoint(v(1, 2, 3)), 0);
        assertVec(v(2, 6, -3), s.applyToVector(v(1, 2, 3)), 0);
    }

    @Test
    public void rotationsBy90DegreesAreRightHandedAndExact() {
        // Tolerance 0: no 6e-17 residue from cos(π/2).
        assertVec(v(0, 0, 1), Affine.rotation(0, 90).applyToVector(v(0, 1, 0)), 0);
        assertVec(v(1, 0, 0), Affine.rotation(1, 90).applyToVector(v(0, 0, 1)), 0);
        assertVec(v(0, 1, 0), Affine.rotation(2, 90).applyToVector(v(1, 0, 0)), 0);
        assertVec(v(-1, 0, 0), Affine.rotation(2, 180).applyToVector(v(1, 0, 0)), 0);
        assertVec(v(0, -1, 0), Affine.rotation(2, 270).applyToVector(v(1, 0, 0)), 0);
        assertVec(v(0, -1, 0), Affine.rotation(2, -90).applyToVector(v(1, 0, 0)), 0);
        assertVec(v(2, 0, -3), Affine.rotation(1, 450).applyToPoint(v(3, 0, 2)), 0);
    }

    @Test
    public void rotationBy30DegreesUsesCosAndSin() {
        double c = Math.sqrt(3) / 2;
        assertVec(v(c, 0.5, 7), Affine.rotation(2, 30).applyToPoint(v(1, 0, 7)), 1e-15);
    }

    @Test
    public void rotationAboutAnUnknownAxisThrows() {
        try {
            Affine.rotation(3, 90);
            fail("axis 3 should be rejected");
        } catch (IllegalArgumentException expected) {
            // the message names the valid axes
        }
    }

    @Test
    public void afterAppliesTheInnerMapFirst() {
        Affine t = Affine.translation(v(1, 0, 0));
        Affine s = Affine.scale(v(2, 2, 2));
        // t.after(s): (1,1,1) → scale (2,2,2) → translate (3,2,2)
        assertVec(v(3, 2, 2), t.after(s).applyToPoint(v(1, 1, 1)), 0);
        // s.after(t): (1,1,1) → translate (2,1,1) → scale (4,2,2)
        assertVec(v(4, 2, 2), s.after(t).applyToPoint(v(1, 1, 1)), 0);
        // Vectors ignore the translation in both orders.
        assertVec(v(2, 2, 2), t.after(s).applyToVector(v(1, 1, 1)), 0);
    }

    @Test
    public void afterMatchesApplyingTheMapsInTurnForRandomMaps() {
        Random random = new Random(42);
        for (int i = 0; i < 100; i++) {
            Affine outer = randomAffine(random);
            Affine inner = randomAffine(random);
            Vec3 p = randomVec(random, 10);
            Vec3 expected = outer.applyToPoint(inner.applyToPoint(p));
            assertVec(expected, outer.after(inner).applyToPoint(p), 1e-12 * (1 + expected.maxAbs()));
        }
    }

    @Test
    public void inverseUndoesRandomTransformsInBothOrders() {
        Random random = new Random(7);
        for (int i = 0; i < 200; i++) {
            Affine a = randomAffine(random);
            Affine inverse = a.inverse();
            Vec3 p = randomVec(random, 10);
            assertVec("A·A⁻¹ for " + a, p, a.after(inverse).applyToPoint(p), 1e-11);
            assertVec("A⁻¹·A for " + a, p, inverse.after(a).applyToPoint(p), 1e-11);
        }
    }

    @Test
    public void inverseOfTranslateRotateScaleIsHandComputed() {
        // A = T(1,2,3)·Rz(90)·S(2,1,1): A(x,y,z) = (1 − y, 2 + 2x, 3 + z).
        Affine a = Affine.translation(v(1, 2, 3)).after(Affine.rotation(2, 90)).after(Affine.scale(v(2, 1, 1)));
        assertVec(v(1, 4, 3), a.applyToPoint(v(1, 0, 0)), 0);
        // So A⁻¹(x,y,z) = ((y − 2)/2, 1 − x, z − 3).
        assertVec(v(1, 0, 0), a.inverse().applyToPoint(v(1, 4, 3)), 1e-15);
        assertVec(v(-1, -4, -3), a.inverse().applyToPoint(v(5, 0, 0)), 1e-15);
    }

    @Test
    public void transposeOfHandMatrix() {
        // M = Rz(90)·S(2,3,1): M(x,y,z) = (−3y, 2x, z), rows [0 −3 0; 2 0 0; 0 0 1],
        // so Mᵀ(x,y,z) = (2y, −3x, z).
        Affine m = Affine.rotation(2, 90).after(Affine.scale(v(2, 3, 1)));
        assertVec(v(-6, 2, 3), m.applyToVector(v(1, 2, 3)), 0);
        assertVec(v(4, -3, 3), m.applyTransposeToVector(v(1, 2, 3)), 0);
    }

    @Test
    public void transposeSatisfiesTheDotProductIdentity() {
        // (M a)·b = a·(Mᵀ b) for every a, b: the defining property of the transpose.
        Random random = new Random(11);
        for (int i = 0; i < 100; i++) {
            Affine m = randomAffine(random);
            Vec3 a = randomVec(random, 1);
            Vec3 b = randomVec(random, 1);
            assertEquals(m.applyToVector(a).dot(b), a.dot(m.applyTransposeToVector(b)), 1e-12);
        }
    }

    @Test
    public void inverseTransposeKeepsNormalsPerpendicularToTransformedTangents() {
        Random random = new Random(13);
        for (int i = 0; i < 100; i++) {
            Affine m = randomAffine(random);
            Vec3 normal = randomVec(random, 1);
            // A tangent: any vector perpendicular to the normal.
            Vec3 tangent = normal.cross(randomVec(random, 1));
            Vec3 worldNormal = m.inverse().applyTransposeToVector(normal);
            Vec3 worldTangent = m.applyToVector(tangent);
            assertEquals(0, worldNormal.normalized().dot(worldTangent.normalized()), 1e-12);
        }
    }

    @Test
    public void determinantOfScaleAndRotation() {
        assertEquals(24, Affine.scale(v(2, 3, 4)).determinant(), 0);
        assertEquals(-2, Affine.scale(v(-1, 1, 2)).determinant(), 0);
        assertEquals(1, Affine.rotation(0, 37).determinant(), 1e-15);
    }

    @Test
    public void singularMatrixCannotBeInverted() {
        try {
            Affine.scale(v(1, 0, 1)).inverse();
            fail("a zero scale is not invertible");
        } catch (IllegalArgumentException expected) {
            assertEquals("the transform cannot be inverted (its determinant is 0.0); expected scales and rotations whose"
                    + " product is nonzero and finite", expected.getMessage());
        }
        try {
            // 5 · 5 · 1.8e308 overflows: the inverse would scale by 0 and lose the axis.
            Affine.scale(v(5, 5, Double.MAX_VALUE)).inverse();
            fail("a scale whose determinant overflows is not invertible");
        } catch (IllegalArgumentException expected) {
            assertEquals("the transform cannot be inverted (its determinant is Infinity); expected scales and rotations whose"
                    + " product is nonzero and finite", expected.getMessage());
        }
    }

    @Test
    public void identityIsRecognized() {
        assertTrue(Affine.IDENTITY.isIdentity());
        assertTrue(Affine.translation(Vec3.ZERO).isIdentity());
        assertTrue(Affine.scale(Vec3.ONE).isIdentity());
        assertFalse(Affine.translation(v(0, 0, 1e-9)).isIdentity());
        assertFalse(Affine.rotation(1, 90).isIdentity());
        // sin(0°) gives −0.0 in the rotation matrix; it is still the identity.
        assertTrue(Affine.rotation(0, 0).isIdentity());
        assertTrue(Affine.rotation(2, 0).isIdentity());
        assertVec(v(4, 5, 6), Affine.IDENTITY.applyToPoint(v(4, 5, 6)), 0);
    }

    @Test
    public void equalMapsAreEqualWithEqualHashes() {
        Affine a = Affine.translation(v(1, 2, 3)).after(Affine.scale(v(2, 2, 2)));
        Affine b = Affine.translation(v(1, 2, 3)).after(Affine.scale(v(2, 2, 2)));
        assertEquals(a, b);
        assertEquals(a.hashCode(), b.hashCode());
        assertFalse(a.equals(Affine.scale(v(2, 2, 2)).after(Affine.translation(v(1, 2, 3)))));
    }

    /** A random T·Rz·Ry·Rx·S with scales of magnitude 0.2 to 5, either sign. */
    static Affine randomAffine(Random random) {
        Vec3 scale = v(randomScale(random), randomScale(random), randomScale(random));
        return Affine.translation(randomVec(random, 10))
                .after(Affine.rotation(2, 360 * random.nextDouble()))
                .after(Affine.rotation(1, 360 * random.nextDouble()))
                .after(Affine.rotation(0, 360 * random.nextDouble()))
                .after(Affine.scale(scale));
    }

    private static double randomScale(Random random) {
        double magnitude = 0.2 + 4.8 * random.nextDouble();
        return random.nextBoolean() ? magnitude : -magnitude;
    }

    static Vec3 randomVec(Random random, double extent) {
        return v(extent * (2 * random.nextDouble() - 1), extent * (2 * random.nextDouble() - 1),
                extent * (2 * random.nextDouble() - 1));
    }
}
