package ray.shading;

import java.math.BigDecimal;
import java.math.MathContext;
import ray.math.Vec3;

/**
 * The microfacet BRDF's terms worked out to 40 significant digits with BigDecimal, from the vectors'
 * exact double values, by the formulas as the course writes them (tan²θ = sin²θ/cos²θ, the sine
 * from Lagrange's identity |a|²|b|² − (a·b)², which is the cross product's squared length exactly):
 * an oracle for D, G1, F and f whose own rounding is far below any test's tolerance.
 */
public final class MicrofacetOracle {
    private static final MathContext MC = new MathContext(40);
    private static final BigDecimal PI = new BigDecimal("3.141592653589793238462643383279502884197169399");
    private static final BigDecimal ONE = BigDecimal.ONE;
    private static final BigDecimal TWO = BigDecimal.valueOf(2);

    private MicrofacetOracle() {
    }

    private static BigDecimal b(double x) {
        return new BigDecimal(x);
    }

    private static BigDecimal dot(Vec3 a, Vec3 c) {
        return b(a.x).multiply(b(c.x), MC).add(b(a.y).multiply(b(c.y), MC), MC).add(b(a.z).multiply(b(c.z), MC), MC);
    }

    /** sin²θ between a and c times |a|²|c|² : |a × c|², exactly as Lagrange's identity gives it. */
    private static BigDecimal crossSquared(Vec3 a, Vec3 c) {
        BigDecimal d = dot(a, c);
        return dot(a, a).multiply(dot(c, c), MC).subtract(d.multiply(d, MC), MC);
    }

    /** e^x for x ≤ 0, by halving x until it is small, summing the Taylor series and squaring back. */
    static BigDecimal exp(BigDecimal x) {
        if (x.signum() > 0) {
            throw new IllegalArgumentException("exp of a positive number: " + x);
        }
        int halvings = 0;
        BigDecimal y = x;
        while (y.abs().compareTo(new BigDecimal("0.001")) > 0) {
            y = y.divide(TWO, MC);
            halvings++;
        }
        BigDecimal sum = ONE;
        BigDecimal term = ONE;
        for (int k = 1; k < 30; k++) {
            term = term.multiply(y, MC).divide(BigDecimal.valueOf(k), MC);
            sum = sum.add(term, MC);
        }
        for (int i = 0; i < halvings; i++) {
            sum = sum.multiply(sum, MC);
            if (sum.signum() == 0 || sum.scale() > 1_000_000) {
                return BigDecimal.ZERO; // far below any double
            }
        }
        return sum;
    }

    /** Beckmann's D = exp(−tan²θ/α²) / (π α² cos⁴θ) for n·h > 0, else 0. */
    public static double beckmannD(double alpha, Vec3 n, Vec3 h) {
        BigDecimal c = dot(n, h);
        if (c.signum() <= 0) {
            return 0;
        }
        BigDecimal c2 = c.multiply(c, MC);
        BigDecimal a2 = b(alpha).multiply(b(alpha), MC);
        BigDecimal tan2 = crossSquared(n, h).divide(c2, MC);
        BigDecimal e = exp(tan2.divide(a2, MC).negate());
        return e.divide(PI.multiply(a2, MC).multiply(c2, MC).multiply(c2, MC), MC).doubleValue();
    }

    /** GGX's D = α² / (π cos⁴θ (α² + tan²θ)²) for n·h > 0, else 0. */
    public static double ggxD(double alpha, Vec3 n, Vec3 h) {
        BigDecimal c = dot(n, h);
        if (c.signum() <= 0) {
            return 0;
        }
        BigDecimal c2 = c.multiply(c, MC);
        BigDecimal a2 = b(alpha).multiply(b(alpha), MC);
        BigDecimal tan2 = crossSquared(n, h).divide(c2, MC);
        BigDecimal s = a2.add(tan2, MC);
        return a2.divide(PI.multiply(c2, MC).multiply(c2, MC).multiply(s, MC).multiply(s, MC), MC).doubleValue();
    }

    /** Beckmann's G1 in the course's rational form: a = 1/(α tanθ), 1 for a ≥ 1.6; 0 unless x·h and x·n agree in sign. */
    public static double beckmannG1(double alpha, Vec3 x, Vec3 n, Vec3 h) {
        BigDecimal xn = dot(x, n);
        if (dot(x, h).multiply(xn, MC).signum() <= 0) {
            return 0;
        }
        BigDecimal s2 = crossSquared(x, n);
        if (s2.signum() <= 0) {
            return 1;
        }
        BigDecimal a = xn.abs().divide(b(alpha).multiply(s2.sqrt(MC), MC), MC);
        if (a.compareTo(new BigDecimal("1.6")) >= 0) {
            return 1;
        }
        BigDecimal a2 = a.multiply(a, MC);
        BigDecimal top = new BigDecimal("3.535").multiply(a, MC).add(new BigDecimal("2.181").multiply(a2, MC), MC);
        BigDecimal bottom = ONE.add(new BigDecimal("2.276").multiply(a, MC), MC).add(new BigDecimal("2.577").multiply(a2, MC), MC);
        return top.divide(bottom, MC).doubleValue();
    }

    /** GGX's G1 = 2 / (1 + √(1 + α² tan²θ)); 0 unless x·h and x·n agree in sign. */
    public static double ggxG1(double alpha, Vec3 x, Vec3 n, Vec3 h) {
        BigDecimal xn = dot(x, n);
        if (dot(x, h).multiply(xn, MC).signum() <= 0) {
            return 0;
        }
        BigDecimal tan2 = crossSquared(x, n).divide(xn.multiply(xn, MC), MC);
        BigDecimal root = ONE.add(b(alpha).multiply(b(alpha), MC).multiply(tan2, MC), MC).sqrt(MC);
        return TWO.divide(ONE.add(root, MC), MC).doubleValue();
    }

    /** The exact dielectric Fresnel reflectance for |l·h| = {@code cosine} and index {@code nt}. */
    public static double fresnel(double nt, double cosine) {
        BigDecimal c = b(cosine);
        BigDecimal g2 = b(nt).multiply(b(nt), MC).subtract(ONE, MC).add(c.multiply(c, MC), MC);
        if (g2.signum() <= 0) {
            return 1;
        }
        BigDecimal g = g2.sqrt(MC);
        BigDecimal first = g.subtract(c, MC).divide(g.add(c, MC), MC);
        BigDecimal second = c.multiply(g.add(c, MC), MC).subtract(ONE, MC).divide(c.multiply(g.subtract(c, MC), MC).add(ONE, MC), MC);
        return first.multiply(first, MC).multiply(ONE.add(second.multiply(second, MC), MC), MC).divide(TWO, MC).doubleValue();
    }

    /**
     * The facets' part of f, F·D·G1(l)·G1(v) / (4 n·l n·v), for unit n, l and v above the surface, with
     * the distribution named "Beckmann" or "GGX"; h is normalize(l + v) worked out here too.
     */
    public static double specular(String distribution, double alpha, double nt, Vec3 n, Vec3 l, Vec3 v) {
        Vec3 h = l.plus(v).normalized();
        boolean beckmann = distribution.equals(MicrofacetDistribution.BECKMANN);
        double d = beckmann ? beckmannD(alpha, n, h) : ggxD(alpha, n, h);
        double gl = beckmann ? beckmannG1(alpha, l, n, h) : ggxG1(alpha, l, n, h);
        double gv = beckmann ? beckmannG1(alpha, v, n, h) : ggxG1(alpha, v, n, h);
        double f = fresnel(nt, Math.abs(l.dot(h)));
        BigDecimal top = b(f).multiply(b(d), MC).multiply(b(gl), MC).multiply(b(gv), MC);
        return top.divide(new BigDecimal(4).multiply(dot(n, l), MC).multiply(dot(n, v), MC), MC).doubleValue();
    }
}
