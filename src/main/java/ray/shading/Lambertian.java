package ray.shading;

import ray.math.Vec3;

/** A matte surface: L = Σ kd ⊙ I · max(0, n·l) / r². */
public class Lambertian extends DirectLighting {

    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        setDiffuseColor(diffuseColor);
    }

    @Override
    protected Vec3 reflectance(Vec3 kd, Vec3 normal, Vec3 toLight, Vec3 toEye) {
        return kd.times(Math.max(0, normal.dot(toLight)));
    }
}
