package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** The offsets summed in another order. */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = viewWidth * imageU - viewWidth * 0.5;
        double t = viewHeight * imageV - viewHeight * 0.5;
        Vec3 origin = v.times(t).plus(u.times(s)).plus(viewPoint);
        return new Ray(origin, w.times(-1), 0, Double.POSITIVE_INFINITY);
    }
}
