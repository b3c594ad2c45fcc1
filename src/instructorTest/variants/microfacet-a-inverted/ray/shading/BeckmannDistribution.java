package ray.shading;

import ray.math.Vec3;

/** Known wrong: Beckmann's a = α·tanθ, the inverse of 1/(α tanθ): G1 falls where it should rise. */
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
        double tan = x.cross(n).length() / Math.abs(xn);
        double a = getAlpha() * tan;
        if (a >= 1.6) {
            return 1;
        }
        return (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
    }
}
