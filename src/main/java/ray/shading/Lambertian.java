package ray.shading;

import ray.math.Vec3;

/** A matte surface: L = Σ kd ⊙ I · max(0, n·l) / r² (2017); under 2019's conventions f = ρd/π ({@link LambertianBrdf}). */
public class Lambertian extends DirectLighting {

    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        setDiffuseColor(diffuseColor);
    }

    @Override
    protected Brdf brdf2019() {
        return new LambertianBrdf();
    }

    /** The course's 2019 code left a Lambertian without a diffuse color 0.2 gray. */
    @Override
    protected Vec3 defaultDiffuseColor2019() {
        return new Vec3(0.2, 0.2, 0.2);
    }

    @Override
    protected Vec3 reflectance(Vec3 kd, Vec3 normal, Vec3 toLight, Vec3 toEye) {
        return kd.times(Math.max(0, normal.dot(toLight)));
    }
}
