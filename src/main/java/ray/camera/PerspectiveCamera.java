package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** A pinhole camera at viewPoint, with its image plane projDistance in front of it (both kept by PinholeCamera). */
public class PerspectiveCamera extends PinholeCamera {

    @Override
    public Ray generateRay(double imageU, double imageV) {
        // TODO(Task 1): make the ray from the eye through image point (imageU, imageV).
        //   The ray starts at the eye (viewPoint) and passes through the image point on the image plane,
        //   a viewWidth × viewHeight rectangle projDistance in front of the eye.
        //   Conventions (the reference images depend on them):
        //   - (imageU, imageV) runs from (0, 0) at the image's lower-left corner to (1, 1) at its
        //     upper-right, and (½, ½) is the center of the view; u points right, v up, and the view
        //     looks along −w.
        //   - The ray's direction may have any length, and its segment is new Ray's own (0 to infinity).
        // HINTS steps
        //   1) Turn (imageU, imageV) into a position on the image plane, measured from its center in units
        //      of the plane's width and height.
        //   2) That point of the plane lies projDistance in front of the eye along the view direction; aim
        //      the ray from the eye at it.
        //   3) Return the ray from the eye with that direction.
        // HINTS formulas
        //   1) The image-plane coordinates: planeU = (imageU − ½)·viewWidth and
        //      planeV = (imageV − ½)·viewHeight (t is kept for the ray's parameter).
        //   2) The ray starts at viewPoint and goes toward that point of the image plane, which lies
        //      projDistance along −w: direction = planeU·u + planeV·v − projDistance·w (no need to
        //      normalize).
        //   3) Return new Ray(origin, direction).
        // END HINTS
        // BEGIN SOLUTION
        double s = (imageU - 0.5) * viewWidth;
        double t = (imageV - 0.5) * viewHeight;
        Vec3 direction = u.times(s).plus(v.times(t)).minus(w.times(projDistance));
        return new Ray(viewPoint, direction);
        // END SOLUTION
        // STUB: return new Ray(viewPoint, w.negate(), 0, 0);
    }
}
