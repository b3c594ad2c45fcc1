package ray.shading;

import ray.math.Vec3;

/** Known wrong: no π: f = ρd, the 2017 diffuse color taken as the BRDF. */
public class LambertianBrdf extends LambertianBrdfFormula {

    public LambertianBrdf() {
    }

    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        return rhoD;
    }
}
