package ray.shading;

import ray.math.Vec3;

/** The ideal diffuse BRDF, f = ρd/π: it reflects the share ρd of what arrives, spread evenly over the hemisphere. */
public final class LambertianBrdf implements Brdf {
    @Override
    public Vec3 value(Vec3 rhoD, Vec3 n, Vec3 l, Vec3 v) {
        return rhoD.times(1 / Math.PI);
    }

    @Override
    public String formula() {
        return "ρd/π";
    }
}
