package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** Ray Tracing in One Weekend's lower-left corner plus fractions of the horizontal and vertical spans. */
public class PerspectiveCamera extends PinholeCamera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        Vec3 horizontal = u.times(viewWidth);
        Vec3 vertical = v.times(viewHeight);
        Vec3 lowerLeft = viewPoint.minus(horizontal.times(0.5)).minus(vertical.times(0.5)).minus(w.times(projDistance));
        Vec3 target = lowerLeft.plus(horizontal.times(imageU)).plus(vertical.times(imageV));
        return new Ray(viewPoint, target.minus(viewPoint));
    }
}
