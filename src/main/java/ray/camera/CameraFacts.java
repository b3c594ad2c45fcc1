package ray.camera;

import ray.math.Vec3;

/** What the framework does with a camera ({@link Camera}) besides asking it for rays. */
final class CameraFacts {
    private CameraFacts() {
    }

    /**
     * Checks the view and computes the course's basis: w = −normalize(viewDir), u =
     * normalize(viewUp × w), v = w × u.
     *
     * @throws IllegalArgumentException for a view that has no such basis, in the scene file's words
     */
    static void complete(Camera c) {
        Vec3 viewDir = c.viewDir;
        Vec3 viewUp = c.viewUp;
        if (!(viewDir.lengthSquared() > 0) || !viewDir.isFinite()) {
            throw new IllegalArgumentException("viewDir is " + viewDir + "; expected a nonzero vector");
        }
        Vec3 w = viewDir.normalized().negate();
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
        c.w = w;
        c.u = side.normalized();
        c.v = w.cross(c.u);
    }

    /** A copy of every field of {@code c}, its viewPoint moved into the frame whose origin is {@code origin}. */
    static Camera inFrameAt(Camera c, Vec3 origin) {
        Camera moved = c.shallowCopy();
        moved.viewPoint = c.viewPoint.minus(origin);
        moved.complete();
        return moved;
    }
}
