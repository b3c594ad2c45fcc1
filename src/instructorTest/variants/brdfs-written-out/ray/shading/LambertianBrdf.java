package ray.shading;

import ray.math.Vec3;

/** Correct: each channel divided by π on its own. */
public class LambertianBrdf extends LambertianBrdfFormula {

    public LambertianBrdf() {
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        return new Vec3(rhoD.x / Math.PI, rhoD.y / Math.PI, rhoD.z / Math.PI);
    }
}
