package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** The ray starts on the image plane, direction viewDir as given (any length). */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = imageU * viewWidth - viewWidth / 2;
        double t = imageV * viewHeight - viewHeight / 2;
        return new Ray(viewPoint.plus(u.times(s).plus(v.times(t))), viewDir.times(3));
    }
}
