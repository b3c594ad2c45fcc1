package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** Known wrong: t measured from the top (the image comes out upside down). */
public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = (imageU - 0.5) * viewWidth;
        double t = (0.5 - imageV) * viewHeight;
        Vec3 direction = u.times(s).plus(v.times(t)).minus(w.times(projDistance));
        return new Ray(viewPoint, direction);
    }
}
