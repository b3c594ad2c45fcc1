package ray.shading;

import ray.math.Vec3;

/** A matte surface: L = Σ kd ⊙ I · max(0, n·l) / r². */
public class Lambertian extends DirectLighting {
    private Vec3 diffuseColor = Vec3.ONE;

    public Lambertian() {
    }

    public Lambertian(Vec3 diffuseColor) {
        this.diffuseColor = diffuseColor;
    }

    public void setDiffuseColor(Vec3 diffuseColor) {
        this.diffuseColor = diffuseColor;
    }

    public Vec3 getDiffuseColor() {
        return diffuseColor;
    }

    @Override
    protected Vec3 reflectance(Vec3 normal, Vec3 toLight, Vec3 toEye) {
        return diffuseColor.times(Math.max(0, normal.dot(toLight)));
    }
}
