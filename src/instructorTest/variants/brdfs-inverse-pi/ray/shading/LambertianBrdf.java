package ray.shading;

import ray.math.Vec3;

/** Correct: 1/π kept as a constant. */
public class LambertianBrdf extends LambertianBrdfFormula {
    static final double INVERSE_PI = 1.0 / Math.PI;

    public LambertianBrdf() {
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        return rhoD.times(INVERSE_PI);
    }
}
