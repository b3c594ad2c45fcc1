package ray.shading;

import ray.math.Vec3;

/** Known wrong: α squared twice in D, α⁴ where the formula has α². */
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
        double alpha2 = getAlpha() * getAlpha();
        alpha2 = alpha2 * alpha2;
        double tan2 = n.cross(h).lengthSquared() / (c * c);
        double falloff = Math.exp(-tan2 / alpha2);
        // Where the exponential has underflowed, c⁴ may have too: 0, never 0/0.
        return falloff == 0 ? 0 : falloff / (Math.PI * alpha2 * (c * c) * (c * c));
    }

    @Override
    public double masking(Vec3 x, Vec3 n, Vec3 h) {
        double xn = x.dot(n);
        if (!(x.dot(h) * xn > 0)) {
            return 0;
        }
        double sine = x.cross(n).length();
        if (sine == 0) {
            return 1; // along the normal: tanθ = 0, a = ∞
        }
        double a = Math.abs(xn) / (getAlpha() * sine);
        if (a >= 1.6) {
            return 1;
        }
        return (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
    }
}
