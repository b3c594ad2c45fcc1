package ray.shading;

import ray.math.Vec3;

/** Known wrong: α squared twice in D, α⁴ where the formula has α². */
public class GgxDistribution extends MicrofacetDistribution {
    public GgxDistribution() {
    }

    public GgxDistribution(double alpha) {
        super(alpha);
    }

    @Override
    public String name() {
        return GGX;
    }

    @Override
    public double normalDistribution(Vec3 n, Vec3 h) {
        double c = n.dot(h);
        if (!(c > 0)) {
            return 0;
        }
        double alpha2 = getAlpha() * getAlpha();
        alpha2 = alpha2 * alpha2;
        double sum = alpha2 * c * c + n.cross(h).lengthSquared();
        return alpha2 / (Math.PI * sum * sum);
    }

    @Override
    public double masking(Vec3 x, Vec3 n, Vec3 h) {
        double xn = x.dot(n);
        if (!(x.dot(h) * xn > 0)) {
            return 0;
        }
        double c = Math.abs(xn);
        double alpha = getAlpha();
        double s2 = x.cross(n).lengthSquared();
        return 2 * c / (c + Math.sqrt(c * c + alpha * alpha * s2));
    }
}
