package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** Known wrong: the −½ left out, so the image plane starts at the view axis instead of being centered on it. */
public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = imageU * viewWidth;
        double t = imageV * viewHeight;
        Vec3 direction = u.times(s).plus(v.times(t)).minus(w.times(projDistance));
        return new Ray(viewPoint, direction);
    }
}
