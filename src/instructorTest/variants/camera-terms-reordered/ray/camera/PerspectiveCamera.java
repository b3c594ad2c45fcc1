package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** The lecture's formula with the terms summed in another order and the start and end written out. */
public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = viewWidth * imageU - viewWidth * 0.5;
        double t = viewHeight * imageV - viewHeight * 0.5;
        Vec3 direction = w.times(-projDistance).plus(v.times(t)).plus(u.times(s));
        return new Ray(viewPoint, direction, 0, Double.POSITIVE_INFINITY);
    }
}
