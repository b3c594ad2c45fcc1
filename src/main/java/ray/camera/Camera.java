package ray.camera;

import ray.Ray;
import ray.math.Vec3;

/**
 * A camera turns a point (u, v) of the image, each in [0, 1] with (0, 0) at the lower left,
 * into the ray that sees it.
 *
 * <p>The camera's orthonormal basis follows the course's convention: w points backward
 * (w = −normalize(viewDir)), u to the right (u = normalize(viewUp × w)), v up (v = w × u).
 * The image plane spans viewWidth × viewHeight, centered on the view axis.
 */
public abstract class Camera implements Cloneable {
    protected Vec3 viewPoint = Vec3.ZERO;
    protected Vec3 viewDir = new Vec3(0, 0, -1);
    protected Vec3 viewUp = new Vec3(0, 1, 0);
    protected double viewWidth = 1.0;
    protected double viewHeight = 1.0;

    /** The camera basis, set by {@link #complete()}. */
    protected Vec3 u;
    protected Vec3 v;
    protected Vec3 w;

    /**
     * The ray through image point (imageU, imageV), both in [0, 1], (0, 0) at the lower left.
     */
    public abstract Ray generateRay(double imageU, double imageV);

    /** Checks the view and computes the basis; called once every property is set. */
    public void complete() {
        if (!(viewDir.lengthSquared() > 0) || !viewDir.isFinite()) {
            throw new IllegalArgumentException("viewDir is " + viewDir + "; expected a nonzero vector");
        }
        w = viewDir.normalized().negate();
        Vec3 side = viewUp.cross(w);
        if (!(side.lengthSquared() > 0) || !side.isFinite()) {
            if (!(viewUp.lengthSquared() > 0)) {
                throw new IllegalArgumentException("viewUp is " + viewUp + "; expected a nonzero vector not parallel to viewDir");
            }
            if (side.lengthSquared() == 0) {
                throw new IllegalArgumentException("viewUp " + viewUp + " is parallel to viewDir " + viewDir
                        + "; expected a viewUp that is not parallel to viewDir");
            }
            // Only a huge viewUp gets here: its cross product with the unit w overflows.
            throw new IllegalArgumentException("viewUp " + viewUp + " is too large; expected a moderate vector not parallel to viewDir");
        }
        u = side.normalized();
        v = w.cross(u);
    }

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
        this.viewWidth = requirePositive("viewWidth", viewWidth);
    }

    public void setViewHeight(double viewHeight) {
        this.viewHeight = requirePositive("viewHeight", viewHeight);
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

    /** The basis vector toward the image's right, once {@link #complete()} has run (null before). */
    public Vec3 getU() {
        return u;
    }

    /** The basis vector toward the image's top, once {@link #complete()} has run (null before). */
    public Vec3 getV() {
        return v;
    }

    /** The basis vector pointing back from the view (−viewDir, unit), once {@link #complete()} has run (null before). */
    public Vec3 getW() {
        return w;
    }

    /**
     * This camera in coordinates whose origin is at {@code origin} (its viewPoint becomes
     * viewPoint − origin; directions and sizes stay): a copy of every field, so that a camera
     * class's own settings come along.
     */
    public Camera inFrameAt(Vec3 origin) {
        Camera moved;
        try {
            moved = (Camera) clone();
        } catch (CloneNotSupportedException e) {
            throw new IllegalStateException(e);
        }
        moved.viewPoint = viewPoint.minus(origin);
        moved.complete();
        return moved;
    }

    protected static double requirePositive(String name, double value) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(name + " is " + value + "; expected a positive number");
        }
        return value;
    }
}
