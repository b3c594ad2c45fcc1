package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** Known wrong: t measured from the top. */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = (imageU - 0.5) * viewWidth;
        double t = (0.5 - imageV) * viewHeight;
        return new Ray(viewPoint.plus(u.times(s)).plus(v.times(t)), w.negate());
    }
}
