package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** A pinhole camera at viewPoint, with its image plane projDistance in front of it (both kept by PinholeCamera). */
public class PerspectiveCamera extends PinholeCamera {

    @Override
    public Ray generateRay(double imageU, double imageV) {
        // TODO(Task 1): make the ray from the eye through image point (imageU, imageV).
        //   1) The image-plane coordinates: planeU = (imageU − ½)·viewWidth and
        //      planeV = (imageV − ½)·viewHeight (t is kept for the ray's parameter).
        //   2) The ray starts at viewPoint and goes toward that point of the image plane, which lies
        //      projDistance along −w: direction = planeU·u + planeV·v − projDistance·w (no need to
        //      normalize).
        //   3) Return new Ray(origin, direction).
        // BEGIN SOLUTION
        double s = (imageU - 0.5) * viewWidth;
        double t = (imageV - 0.5) * viewHeight;
        Vec3 direction = u.times(s).plus(v.times(t)).minus(w.times(projDistance));
        return new Ray(viewPoint, direction);
        // END SOLUTION
        // STUB: return new Ray(viewPoint, w.negate(), 0, 0);
    }
}
