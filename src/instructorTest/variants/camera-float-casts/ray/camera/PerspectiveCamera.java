package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** Known wrong: computes the image-plane coordinates in float, (float) ((imageU − 0.5)·viewWidth), so rays are off by float rounding, some 1e-8 of the view. */
public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = (float) ((imageU - 0.5) * viewWidth);
        double t = (float) ((imageV - 0.5) * viewHeight);
        Vec3 direction = u.times(s).plus(v.times(t)).minus(w.times(projDistance));
        return new Ray(viewPoint, direction);
    }
}
