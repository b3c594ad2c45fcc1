package ray.shading;

import ray.math.Vec3;

/** Correct: D as 1/exp(tan²θ/α²) over π α² cos⁴θ, with cos⁴θ and tan²θ from the squared cosine and the cross product; G1 through a helper. */
public class BeckmannDistribution extends MicrofacetDistribution {
    public BeckmannDistribution() {
    }

    public BeckmannDistribution(double alpha) {
        super(alpha);
    }

    @Override
    public String name() {
        return BECKMANN;
    }

    @Override
    public double normalDistribution(Vec3 n, Vec3 h) {
        double c = n.dot(h);
        if (!(c > 0)) {
            return 0;
        }
        double c2 = c * c;
        double s2 = n.cross(h).lengthSquared();
        double a2 = getAlpha() * getAlpha();
        double grow = Math.exp(s2 / (c2 * a2));
        if (Double.isInfinite(grow)) {
            return 0;
        }
        return 1 / (grow * Math.PI * a2 * c2 * c2);
    }

    @Override
    public double masking(Vec3 x, Vec3 n, Vec3 h) {
        if (Math.signum(x.dot(h)) != Math.signum(x.dot(n)) || x.dot(n) == 0) {
            return 0;
        }
        double c = Math.abs(x.dot(n));
        double s = Math.sqrt(x.cross(n).lengthSquared());
        return s == 0 ? 1 : rational(c / (getAlpha() * s));
    }

    private static double rational(double a) {
        return a >= 1.6 ? 1 : a * (3.535 + 2.181 * a) / (1 + a * (2.276 + 2.577 * a));
    }
}
