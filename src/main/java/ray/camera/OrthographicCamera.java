package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** A parallel projection: every ray points along viewDir, from its own point of the image plane. */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        // TODO(Task 1): make the ray through image point (imageU, imageV) of an orthographic view.
        //   1) The image-plane coordinates: planeU = (imageU − ½)·viewWidth and
        //      planeV = (imageV − ½)·viewHeight (t is kept for the ray's parameter).
        //   2) The ray starts on the image plane, at viewPoint + planeU·u + planeV·v, and points along −w.
        //   3) Return new Ray(origin, direction).
        // BEGIN SOLUTION
        double s = (imageU - 0.5) * viewWidth;
        double t = (imageV - 0.5) * viewHeight;
        Vec3 origin = viewPoint.plus(u.times(s)).plus(v.times(t));
        return new Ray(origin, w.negate());
        // END SOLUTION
        // STUB: return new Ray(viewPoint, w.negate(), 0, 0);
    }
}
