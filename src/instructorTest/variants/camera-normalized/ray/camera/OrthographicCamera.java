package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** A unit direction, normalized again though −w already is one. */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        double s = (imageU - 0.5) * viewWidth;
        double t = (imageV - 0.5) * viewHeight;
        Vec3 origin = viewPoint.plus(u.times(s)).plus(v.times(t));
        return new Ray(origin, w.negate().normalized());
    }
}
