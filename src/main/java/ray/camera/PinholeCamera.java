package ray.camera;

import ray.math.PositiveNumber;

/**
 * A pinhole camera's data and everything about it but the ray, which the student's
 * {@link PerspectiveCamera} adds: every ray starts at viewPoint and passes through the image plane,
 * which lies {@code projDistance} in front of it (along −w), as SphereSurface holds a sphere's data
 * for the student's Sphere.
 */
public abstract class PinholeCamera extends Camera {
    protected double projDistance = 1.0;

    public void setProjDistance(double projDistance) {
        this.projDistance = PositiveNumber.require("projDistance", projDistance);
    }

    public double getProjDistance() {
        return projDistance;
    }
}
