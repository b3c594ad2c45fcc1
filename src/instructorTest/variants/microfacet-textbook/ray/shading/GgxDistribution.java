package ray.shading;

import ray.math.Vec3;

/** Correct: the textbook forms, D = α²/(π cos⁴θ (α² + tan²θ)²) and G1 = 2/(1 + √(1 + α² tan²θ)), tan²θ = (1 − cos²θ)/cos²θ. */
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
        double cos = n.dot(h);
        if (cos <= 0) {
            return 0;
        }
        double cos2 = cos * cos;
        double tan2 = (1 - cos2) / cos2;
        double a2 = getAlpha() * getAlpha();
        double s = a2 + tan2;
        return a2 / (Math.PI * cos2 * cos2 * s * s);
    }

    @Override
    public double masking(Vec3 x, Vec3 n, Vec3 h) {
        double xn = x.dot(n);
        if (x.dot(h) / xn <= 0) {
            return 0;
        }
        double c2 = xn * xn;
        double tan2 = (1 - c2) / c2;
        return 2 / (1 + Math.sqrt(1 + getAlpha() * getAlpha() * tan2));
    }
}
