package ray.surface;

import ray.math.Affine;
import ray.math.Vec3;

/**
 * Where a surface is placed in its parent: translate, then rotate (degrees about x, then y, then
 * z), then scale, composed as T·Rz·Ry·Rx·S. The scene loader reads {@code <translate>},
 * {@code <rotate>} and {@code <scale>} of a group, box or mesh into one and wraps the surface in a
 * {@link Transformed} when it is not the identity, so no surface carries its own transform.
 */
public final class Placement {
    private Vec3 translate = Vec3.ZERO;
    private Vec3 rotateDegrees = Vec3.ZERO;
    private Vec3 scale = Vec3.ONE;

    /** The placement translate·rotate·scale, for code that builds scenes. */
    public static Placement of(Vec3 translate, Vec3 rotateDegrees, Vec3 scale) {
        Placement placement = new Placement();
        placement.setTranslate(translate);
        placement.setRotate(rotateDegrees);
        placement.setScale(scale);
        return placement;
    }

    public void setTranslate(Vec3 translate) {
        this.translate = translate;
    }

    public void setRotate(Vec3 degreesAboutXYZ) {
        this.rotateDegrees = degreesAboutXYZ;
    }

    public void setScale(Vec3 scale) {
        this.scale = scale;
    }

    /** The map from the placed surface's coordinates to its parent's: T·Rz·Ry·Rx·S. */
    public Affine toWorld() {
        return Affine.translation(translate)
                .after(Affine.rotation(2, rotateDegrees.z))
                .after(Affine.rotation(1, rotateDegrees.y))
                .after(Affine.rotation(0, rotateDegrees.x))
                .after(Affine.scale(scale));
    }

    /**
     * {@code surface} placed: itself when this is the identity, else wrapped in a {@link Transformed}.
     *
     * @throws IllegalArgumentException when the scale is zero on an axis (the map has no inverse)
     */
    public Surface place(Surface surface) {
        if (scale.x == 0 || scale.y == 0 || scale.z == 0) {
            throw new IllegalArgumentException("scale " + scale + " is zero on an axis; expected a nonzero scale on every axis");
        }
        Affine toWorld = toWorld();
        return toWorld.isIdentity() ? surface : new Transformed(surface, toWorld);
    }
}
