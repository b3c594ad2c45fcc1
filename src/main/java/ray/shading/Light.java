package ray.shading;

import ray.math.Vec3;

/** A point light: radiant intensity {@code intensity} (RGB) at {@code position}, falling off as 1/r². */
public class Light {
    private Vec3 position = Vec3.ZERO;
    private Vec3 intensity = Vec3.ONE;

    public Light() {
    }

    public Light(Vec3 position, Vec3 intensity) {
        this.position = position;
        this.intensity = intensity;
    }

    public Vec3 getPosition() {
        return position;
    }

    public void setPosition(Vec3 position) {
        this.position = position;
    }

    public Vec3 getIntensity() {
        return intensity;
    }

    public void setIntensity(Vec3 intensity) {
        this.intensity = intensity;
    }

    @Override
    public String toString() {
        return "Light[at " + position + ", intensity " + intensity + "]";
    }
}
