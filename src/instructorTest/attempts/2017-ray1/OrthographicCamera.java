package ray.camera;

import ray.Ray;
import ray.math.Vec3;

public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        float s = (float) (imageU - 0.5) * (float) viewWidth;
        float t = (float) (imageV - 0.5) * (float) viewHeight;
        Vec3 origin = viewPoint.plus(u.times(s)).plus(v.times(t));
        return new Ray(origin, w.times(-1));
    }
}
