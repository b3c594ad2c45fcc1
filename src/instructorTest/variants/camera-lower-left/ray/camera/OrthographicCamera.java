package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** The lower-left corner of the image plane plus fractions of its spans. */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        Vec3 lowerLeft = viewPoint.minus(u.times(viewWidth / 2)).minus(v.times(viewHeight / 2));
        Vec3 origin = lowerLeft.plus(u.times(imageU * viewWidth)).plus(v.times(imageV * viewHeight));
        return new Ray(origin, viewDir);
    }
}
