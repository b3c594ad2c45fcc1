package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** The direction divided by projDistance (−w plus the image offsets over d): a positive multiple of the lecture's. */
public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = (imageU - 0.5) * viewWidth / projDistance;
        double t = (imageV - 0.5) * viewHeight / projDistance;
        return new Ray(viewPoint, w.negate().plus(u.times(s)).plus(v.times(t)));
    }
}
