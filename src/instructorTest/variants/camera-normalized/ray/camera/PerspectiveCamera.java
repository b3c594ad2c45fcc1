package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** A unit direction, as many students (and Ray Tracing in One Weekend) make it: the same ray. */
public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = (imageU - 0.5) * viewWidth;
        double t = (imageV - 0.5) * viewHeight;
        Vec3 direction = u.times(s).plus(v.times(t)).minus(w.times(projDistance));
        return new Ray(viewPoint, direction.normalized());
    }
}
