package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/** A parallel projection: every ray points along viewDir, from its own point of the image plane. */
public class OrthographicCamera extends Camera {
    @Override
    public Ray generateRay(double imageU, double imageV) {
        // TODO(Task 1): make the ray through image point (imageU, imageV) of an orthographic view.
        //   Every ray looks straight ahead and starts on the view's plane, a viewWidth × viewHeight
        //   rectangle centered on viewPoint, at the image point.
        //   Conventions (the reference images depend on them):
        //   - (imageU, imageV) runs from (0, 0) at the image's lower-left corner to (1, 1) at its
        //     upper-right, and (½, ½) is the center of the view; u points right, v up, and the view
        //     looks along −w.
        //   - The ray's direction may have any length, and its segment is new Ray's own (0 to infinity).
        // HINTS steps
        //   1) Turn (imageU, imageV) into a position on the view's plane, measured from its center in units
        //      of the view's width and height.
        //   2) The ray starts at that point of the plane (through viewPoint, spanned by u and v) and looks
        //      along the view direction.
        //   3) Return that ray.
        // HINTS formulas
        //   1) The image-plane coordinates: planeU = (imageU − ½)·viewWidth and
        //      planeV = (imageV − ½)·viewHeight (t is kept for the ray's parameter).
        //   2) The ray starts on the image plane, at viewPoint + planeU·u + planeV·v, and points along −w.
        //   3) Return new Ray(origin, direction).
        // END HINTS
        // BEGIN SOLUTION
        double s = (imageU - 0.5) * viewWidth;
        double t = (imageV - 0.5) * viewHeight;
        Vec3 origin = viewPoint.plus(u.times(s)).plus(v.times(t));
        return new Ray(origin, w.negate());
        // END SOLUTION
        // STUB: return new Ray(viewPoint, w.negate(), 0, 0);
    }
}
