package ray.camera;

import ray.Ray;
import ray.math.Vec3;

public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        float s = (float) (imageU - 0.5) * (float) viewWidth;
        float t = (float) (imageV - 0.5) * (float) viewHeight;
        Vec3 dir = u.times(s).plus(v.times(t)).plus(w.times(-projDistance));
        return new Ray(viewPoint, dir);
    }
}
