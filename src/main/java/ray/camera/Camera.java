package ray.camera;

import ray.Ray;
import ray.math.PositiveNumber;
import ray.math.Vec3;

/**
 * A camera turns a point (u, v) of the image, each in [0, 1] with (0, 0) at the lower left,
 * into the ray that sees it.
 *
 * <p>The camera's orthonormal basis follows the course's convention: w points backward
 * (w = −normalize(viewDir)), u to the right (u = normalize(viewUp × w)), v up (v = w × u).
 * The image plane spans viewWidth × viewHeight, centered on the view axis. (What the framework
 * does with a camera besides, checking it and computing the basis, is in {@link CameraFacts}.)
 */
public abstract class Camera implements FrameworkCamera, Cloneable {
    protected Vec3 viewPoint = Vec3.ZERO;
    protected Vec3 viewDir = new Vec3(0, 0, -1);
    protected Vec3 viewUp = new Vec3(0, 1, 0);
    protected double viewWidth = 1.0;
    protected double viewHeight = 1.0;

    /** The camera basis, set by complete() once every property is set ({@link CameraFacts#complete}). */
    protected Vec3 u;
    protected Vec3 v;
    protected Vec3 w;

    /**
     * The ray through image point (imageU, imageV), both in [0, 1], (0, 0) at the lower left.
     */
    public abstract Ray generateRay(double imageU, double imageV);

    public void setViewPoint(Vec3 viewPoint) {
        this.viewPoint = viewPoint;
    }

    public void setViewDir(Vec3 viewDir) {
        this.viewDir = viewDir;
    }

    public void setViewUp(Vec3 viewUp) {
        this.viewUp = viewUp;
    }

    public void setViewWidth(double viewWidth) {
        this.viewWidth = PositiveNumber.require("viewWidth", viewWidth);
    }

    public void setViewHeight(double viewHeight) {
        this.viewHeight = PositiveNumber.require("viewHeight", viewHeight);
    }

    public Vec3 getViewPoint() {
        return viewPoint;
    }

    public Vec3 getViewDir() {
        return viewDir;
    }

    public Vec3 getViewUp() {
        return viewUp;
    }

    public double getViewWidth() {
        return viewWidth;
    }

    public double getViewHeight() {
        return viewHeight;
    }

    /** The basis vector toward the image's right, once complete() has run (null before). */
    public Vec3 getU() {
        return u;
    }

    /** The basis vector toward the image's top, once complete() has run (null before). */
    public Vec3 getV() {
        return v;
    }

    /** The basis vector pointing back from the view (−viewDir, unit), once complete() has run (null before). */
    public Vec3 getW() {
        return w;
    }

    /** A shallow copy (same class, same fields), for the framework to move ({@link CameraFacts#inFrameAt}). */
    final Camera shallowCopy() {
        try {
            return (Camera) clone();
        } catch (CloneNotSupportedException e) {
            throw new IllegalStateException(e);
        }
    }
}
