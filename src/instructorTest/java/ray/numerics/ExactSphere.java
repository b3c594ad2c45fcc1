package ray.numerics;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import ray.Ray;
import ray.math.Vec3;

/**
 * The exact answer of a ray–sphere test for the very doubles a surface receives: a BigDecimal
 * oracle for the numerics tests (test code only; far too slow to render with).
 *
 * <p>Every double converts exactly ({@code new BigDecimal(double)}), and sums and products of
 * BigDecimals are exact, so the quarter discriminant Δ' = (f·d)² − (d·d)(f·f − r²), with
 * f = origin − center, has its exact value and sign: the classification hit/miss is exact. The roots
 * need a square root, taken to {@link #DIGITS} significant digits with the stable form
 * q = −(b' + sign(b')√Δ'), roots q/a and c/q, so each root keeps those digits relative to itself.
 * Inputs must be finite.
 */
final class ExactSphere {
    /** Significant digits of the roots: far beyond a double's 17, so the oracle's own error is nil. */
    static final int DIGITS = 60;
    private static final MathContext MC = new MathContext(DIGITS, RoundingMode.HALF_EVEN);
    private static final MathContext WORKING = new MathContext(DIGITS + 10, RoundingMode.HALF_EVEN);

    /** (f·d)² − (d·d)(f·f − r²), exact: one quarter of the textbook b² − 4ac. */
    final BigDecimal quarterDiscriminant;
    /** Whether a root lies in (ray.start, ray.end), exactly as Surface.intersect promises. */
    final boolean hit;
    /** The root a correct intersect returns (the smaller one in range), to DIGITS digits; null on a miss. */
    final BigDecimal t;
    private final double a;
    private final double fLength;
    private final double radius;

    private ExactSphere(BigDecimal quarterDiscriminant, boolean hit, BigDecimal t, double a, double fLength, double radius) {
        this.quarterDiscriminant = quarterDiscriminant;
        this.hit = hit;
        this.t = t;
        this.a = a;
        this.fLength = fLength;
        this.radius = radius;
    }

    /**
     * Only the exact hit/miss, without the square root when the ray is the usual (0, ∞) segment: then
     * a root t &gt; 0 exists iff Δ' ≥ 0 and (c &lt; 0, the origin inside, or b' &lt; 0, heading toward the
     * center), since the roots' product is c/a and their sum −2b'/a.
     */
    static boolean hits(Ray ray, Vec3 center, double radius) {
        if (ray.start != 0 || ray.end != Double.POSITIVE_INFINITY) {
            return of(ray, center, radius).hit;
        }
        BigDecimal[] abc = coefficients(ray, center, radius);
        return quarterDiscriminant(abc).signum() >= 0 && (abc[2].signum() < 0 || abc[1].signum() < 0);
    }

    static ExactSphere of(Ray ray, Vec3 center, double radius) {
        BigDecimal[] abc = coefficients(ray, center, radius);
        BigDecimal a = abc[0];
        BigDecimal halfB = abc[1];
        BigDecimal c = abc[2];
        BigDecimal disc = quarterDiscriminant(abc);
        double fLength = ray.origin.minus(center).length();
        double aDouble = ray.direction.dot(ray.direction);
        if (disc.signum() < 0) {
            return new ExactSphere(disc, false, null, aDouble, fLength, radius);
        }
        // Stable quadratic: q never cancels, and c/q gives the other root to full relative precision.
        // Rounding Δ' to a few more digits first changes √Δ' by far less than DIGITS carry, and spares
        // BigDecimal.sqrt the hundreds of digits an exact Δ' has (several times faster).
        BigDecimal root = disc.round(WORKING).sqrt(MC);
        BigDecimal q = halfB.signum() >= 0 ? halfB.add(root).negate() : root.subtract(halfB);
        BigDecimal t0;
        BigDecimal t1;
        if (q.signum() == 0) {
            // b' = 0 and Δ' = 0, so a·c = 0: both roots are 0.
            t0 = BigDecimal.ZERO;
            t1 = BigDecimal.ZERO;
        } else {
            t0 = q.divide(a, MC);
            t1 = c.divide(q, MC);
        }
        BigDecimal near = t0.min(t1);
        BigDecimal far = t0.max(t1);
        BigDecimal t = inRange(near, ray) ? near : inRange(far, ray) ? far : null;
        return new ExactSphere(disc, t != null, t, aDouble, fLength, radius);
    }

    /**
     * Δ'/(a·|f|·r) in units of the double epsilon 2⁻⁵²: how far this ray is from tangency, measured
     * against the rounding error the closest-approach discriminant r² − l·l can carry (its vector
     * l = f − (f·d̂)d̂ is computed from f, of length |f|, so its absolute error grows like ε·|f|).
     */
    double tangencyMargin() {
        return quarterDiscriminant.doubleValue() / a / (fLength * radius) / Math.ulp(1.0);
    }

    /**
     * How far the exact root moves, to first order, when every input moves by a relative 2⁻⁵²
     * (origin, center and direction by that fraction of their length, the radius by that fraction of
     * itself): |δt| ≤ ε·(r + |o| + |c| + t·|d|)·r / (|d|·√(Δ'/a)). From |p − c|² = r² at the hit p:
     * n·(δo − δc + t·δd) + (n·d)·δt = δr, and |n·d| = |d|·√(Δ'/a)/r (|d| times the cosine of
     * incidence). A backward-stable double algorithm (the exact root of inputs moved by a few ulps) can
     * promise no better without extra precision. κ grows without bound at tangency and, relative to t,
     * like |o|/t for an origin near a huge sphere. Only on a hit.
     */
    double conditionBound(Ray ray, Vec3 center) {
        double dLength = ray.direction.length();
        double tangential = Math.sqrt(quarterDiscriminant.doubleValue() / a);
        double scale = radius + ray.origin.length() + center.length() + t.doubleValue() * dLength;
        return Math.ulp(1.0) * scale * radius / (dLength * tangential);
    }

    /** |computed − t| / t, the relative error of a computed root; only on a hit. */
    double relativeError(double computed) {
        BigDecimal exact = t;
        if (exact.signum() == 0) {
            return computed == 0 ? 0 : Double.POSITIVE_INFINITY;
        }
        return new BigDecimal(computed).subtract(exact).abs().divide(exact.abs(), MC).doubleValue();
    }

    /** |computed − t|, the absolute error of a computed root; only on a hit. */
    double absoluteError(double computed) {
        return new BigDecimal(computed).subtract(t).abs().doubleValue();
    }

    /** |computed − t| in units of the ulp of the double nearest to t; only on a hit. */
    double ulpsOff(double computed) {
        double nearest = t.doubleValue();
        return new BigDecimal(computed).subtract(t).abs().doubleValue() / Math.ulp(nearest);
    }

    private static boolean inRange(BigDecimal t, Ray ray) {
        boolean afterStart = ray.start == Double.NEGATIVE_INFINITY || t.compareTo(new BigDecimal(ray.start)) > 0;
        boolean beforeEnd = ray.end == Double.POSITIVE_INFINITY || t.compareTo(new BigDecimal(ray.end)) < 0;
        return afterStart && beforeEnd;
    }

    /** a = d·d, b' = f·d, c = f·f − r², all exact. */
    private static BigDecimal[] coefficients(Ray ray, Vec3 center, double radius) {
        BigDecimal[] d = exact(ray.direction);
        BigDecimal[] o = exact(ray.origin);
        BigDecimal[] ctr = exact(center);
        BigDecimal[] f = {o[0].subtract(ctr[0]), o[1].subtract(ctr[1]), o[2].subtract(ctr[2])};
        BigDecimal r = new BigDecimal(radius);
        return new BigDecimal[] {dot(d, d), dot(f, d), dot(f, f).subtract(r.multiply(r))};
    }

    private static BigDecimal quarterDiscriminant(BigDecimal[] abc) {
        return abc[1].multiply(abc[1]).subtract(abc[0].multiply(abc[2]));
    }

    private static BigDecimal[] exact(Vec3 v) {
        return new BigDecimal[] {new BigDecimal(v.x), new BigDecimal(v.y), new BigDecimal(v.z)};
    }

    private static BigDecimal dot(BigDecimal[] u, BigDecimal[] v) {
        return u[0].multiply(v[0]).add(u[1].multiply(v[1])).add(u[2].multiply(v[2]));
    }
}
