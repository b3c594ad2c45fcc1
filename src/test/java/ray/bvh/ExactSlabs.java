package ray.bvh;

import java.math.BigDecimal;
import ray.Ray;

/**
 * Whether a ray meets a closed box for some t in [ray.start, ray.end], in exact arithmetic: each
 * slab's distances as fractions of BigDecimals (every double is one exactly), compared by cross
 * multiplication, so no rounding decides a touch.
 */
public final class ExactSlabs {
    private ExactSlabs() {
    }

    /** A fraction num/den with den > 0; an infinite end of the ray is null. */
    private static final class Fraction {
        final BigDecimal num;
        final BigDecimal den;

        Fraction(BigDecimal num, BigDecimal den) {
            if (den.signum() < 0) {
                num = num.negate();
                den = den.negate();
            }
            this.num = num;
            this.den = den;
        }

        int compareTo(Fraction o) {
            return num.multiply(o.den).compareTo(o.num.multiply(den));
        }
    }

    public static boolean hits(Box box, Ray ray) {
        Fraction near = Double.isInfinite(ray.start) ? null : new Fraction(new BigDecimal(ray.start), BigDecimal.ONE);
        Fraction far = Double.isInfinite(ray.end) ? null : new Fraction(new BigDecimal(ray.end), BigDecimal.ONE);
        for (int axis = 0; axis < 3; axis++) {
            BigDecimal o = new BigDecimal(ray.origin.get(axis));
            BigDecimal d = new BigDecimal(ray.direction.get(axis));
            BigDecimal min = new BigDecimal(box.min.get(axis));
            BigDecimal max = new BigDecimal(box.max.get(axis));
            if (d.signum() == 0) {
                if (o.compareTo(min) < 0 || o.compareTo(max) > 0) {
                    return false;
                }
                continue;
            }
            Fraction t0 = new Fraction(min.subtract(o), d);
            Fraction t1 = new Fraction(max.subtract(o), d);
            if (t0.compareTo(t1) > 0) {
                Fraction swap = t0;
                t0 = t1;
                t1 = swap;
            }
            if (near == null || t0.compareTo(near) > 0) {
                near = t0;
            }
            if (far == null || t1.compareTo(far) < 0) {
                far = t1;
            }
        }
        return near == null || far == null || near.compareTo(far) <= 0;
    }
}
