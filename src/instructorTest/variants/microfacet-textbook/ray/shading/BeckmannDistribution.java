package ray.shading;

import ray.math.Vec3;

/** Correct: the textbook forms, tan²θ = sin²θ/cos²θ with sin²θ = 1 − cos²θ, and G1 through tanθ = √(1 − c²)/c. */
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
        double cos = n.dot(h);
        if (cos <= 0) {
            return 0;
        }
        double cos2 = cos * cos;
        double tan2 = (1 - cos2) / cos2;
        double a = getAlpha();
        return Math.exp(-tan2 / (a * a)) / (Math.PI * a * a * cos2 * cos2);
    }

    @Override
    public double masking(Vec3 x, Vec3 n, Vec3 h) {
        double xn = x.dot(n);
        double xh = x.dot(h);
        if (xh / xn <= 0) {
            return 0;
        }
        double c = Math.abs(xn);
        double tan = Math.sqrt(Math.max(0, 1 - c * c)) / c;
        double a = 1 / (getAlpha() * tan);
        if (a >= 1.6) {
            return 1;
        }
        return (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
    }
}
