package ray.numerics;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static ray.testing.Asserts.assertVec;

import java.math.BigDecimal;
import org.junit.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Vec3;

/**
 * The two yardsticks of the sphere catalogue on hand-computed cases: ExactSphere (the oracle) and
 * TextbookSphere (the comparison). If either were wrong, the catalogue's agreement and failure rates
 * would mean nothing.
 *
 * <p>The case: unit sphere at the origin, ray from (0, 0, 5) with direction (0, 0, −2), so
 * f = (0, 0, 5), a = 4, b' = f·d = −10, c = 25 − 1 = 24, Δ' = 100 − 96 = 4, roots (10 ∓ 2)/4 = 2 and 3.
 */
public class SphereBaselinesTest {
    private static final Ray RAY = new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -2));

    @Test
    public void oracleGivesTheExactDiscriminantAndNearRoot() {
        ExactSphere exact = ExactSphere.of(RAY, Vec3.ZERO, 1);
        assertEquals(0, new BigDecimal(4).compareTo(exact.quarterDiscriminant));
        assertTrue(exact.hit);
        assertEquals(0, new BigDecimal(2).compareTo(exact.t));
    }

    @Test
    public void oracleTakesTheFarRootWhenTheNearOneIsBeforeStart() {
        ExactSphere exact = ExactSphere.of(new Ray(RAY.origin, RAY.direction, 2.5, Double.POSITIVE_INFINITY), Vec3.ZERO, 1);
        assertEquals(0, new BigDecimal(3).compareTo(exact.t));
        assertFalse(ExactSphere.of(new Ray(RAY.origin, RAY.direction, 0, 1.5), Vec3.ZERO, 1).hit);
    }

    @Test
    public void oracleRootsCarrySixtyDigits() {
        // Radius √2's double r: roots 5 ∓ r·(1/1), with r² = 2 to 1 ulp; t = 5 − r exactly in decimal.
        double r = Math.sqrt(2);
        ExactSphere exact = ExactSphere.of(new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1)), Vec3.ZERO, r);
        BigDecimal expected = new BigDecimal(5).subtract(new BigDecimal(r));
        assertTrue("oracle t " + exact.t, exact.t.subtract(expected).abs().compareTo(new BigDecimal("1e-58")) < 0);
    }

    @Test
    public void oracleCallsATangentRayAHitAndAMissAMiss() {
        // Impact parameter 1 exactly: Δ' = (−5)² − 1·(26 − 1) = 0, double root t = 5.
        ExactSphere tangent = ExactSphere.of(new Ray(new Vec3(-5, 1, 0), new Vec3(1, 0, 0)), Vec3.ZERO, 1);
        assertEquals(0, tangent.quarterDiscriminant.signum());
        assertEquals(0, new BigDecimal(5).compareTo(tangent.t));
        ExactSphere miss = ExactSphere.of(new Ray(new Vec3(-5, 2, 0), new Vec3(1, 0, 0)), Vec3.ZERO, 1);
        assertFalse(miss.hit);
        assertNull(miss.t);
    }

    @Test
    public void fastClassificationAgreesWithTheFullOracle() {
        // On the sphere: roots 0 and 2 (hit at 2, heading in) or 0 and −2 (a miss, heading out).
        Ray in = new Ray(new Vec3(0, 0, 1), new Vec3(0, 0, -1));
        Ray out = new Ray(new Vec3(0, 0, 1), new Vec3(0, 0, 1));
        assertTrue(ExactSphere.hits(in, Vec3.ZERO, 1) && ExactSphere.of(in, Vec3.ZERO, 1).hit);
        assertFalse(ExactSphere.hits(out, Vec3.ZERO, 1) || ExactSphere.of(out, Vec3.ZERO, 1).hit);
        // Inside (c < 0) heading out: b' > 0, still a hit.
        Ray inside = new Ray(new Vec3(0.5, 0, 0), new Vec3(1, 0, 0));
        assertTrue(ExactSphere.hits(inside, Vec3.ZERO, 1) && ExactSphere.of(inside, Vec3.ZERO, 1).hit);
        for (int e = 3; e <= 8; e++) {
            SilhouetteRays rays = new SilhouetteRays(900 + e, Math.pow(10, e), SilhouetteRays.NEAR_SILHOUETTE);
            for (int i = 0; i < 100; i++) {
                SphereCase k = rays.next();
                assertEquals(k.toString(), k.exact().hit, k.exactlyHit());
            }
        }
    }

    @Test
    public void textbookSphereFindsTheNearRootAndItsNormal() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(new TextbookSphere(Vec3.ZERO, 1).intersect(out, RAY));
        assertEquals(2, out.t, 0);
        assertVec(new Vec3(0, 0, 1), out.location, 0);
        assertVec(new Vec3(0, 0, 1), out.normal, 0);
    }

    @Test
    public void textbookSphereTakesTheFarRootFromInsideAndMissesBeside() {
        IntersectionRecord out = new IntersectionRecord();
        assertTrue(new TextbookSphere(Vec3.ZERO, 1).intersect(out, new Ray(Vec3.ZERO, new Vec3(0, 2, 0))));
        assertEquals(0.5, out.t, 0);
        assertFalse(new TextbookSphere(Vec3.ZERO, 1).intersect(new IntersectionRecord(), new Ray(new Vec3(-5, 2, 0), new Vec3(1, 0, 0))));
    }
}
