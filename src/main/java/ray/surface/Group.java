package ray.surface;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.math.Vec3;
import ray.shading.Shader;

/**
 * A list of surfaces, hit by the closest of them. A group may also place its children with a
 * transform T·Rz·Ry·Rx·S (translate, rotate in degrees about x then y then z, scale).
 */
public class Group extends Surface {
    protected final List<Surface> surfaces = new ArrayList<>();
    private Vec3 translate = Vec3.ZERO;
    private Vec3 rotateDegrees = Vec3.ZERO;
    private Vec3 scale = Vec3.ONE;

    public void addSurface(Surface surface) {
        surfaces.add(surface);
    }

    @Override
    public List<Surface> children() {
        return Collections.unmodifiableList(surfaces);
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

    /** The map from this group's coordinates to its parent's: T·Rz·Ry·Rx·S. */
    public Affine placement() {
        return Affine.translation(translate)
                .after(Affine.rotation(2, rotateDegrees.z))
                .after(Affine.rotation(1, rotateDegrees.y))
                .after(Affine.rotation(0, rotateDegrees.x))
                .after(Affine.scale(scale));
    }

    @Override
    public void inheritShader(Shader inherited) {
        if (getShader() == null) {
            setShader(inherited);
            passShaderToChildren();
        }
    }

    private void passShaderToChildren() {
        if (getShader() != null) {
            for (Surface s : surfaces) {
                s.inheritShader(getShader());
            }
        }
    }

    /** Passes this group's shader to children without one, and wraps the group in its transform if it has one. */
    @Override
    public Surface complete() {
        if (scale.x == 0 || scale.y == 0 || scale.z == 0) {
            throw new IllegalArgumentException("scale " + scale + " is zero on an axis; expected a nonzero scale on every axis");
        }
        passShaderToChildren();
        Affine placement = placement();
        return placement.isIdentity() ? this : new Transformed(this, placement);
    }

    @Override
    public boolean intersect(IntersectionRecord out, Ray ray) {
        // TODO(Task 4): find the closest hit among this group's surfaces.
        //   1) Test the surfaces in order against a copy of the ray (ray.copy()), which you may shorten.
        //   2) After each hit, shorten the copy to end at that hit's t, so that only closer hits count
        //      from then on (and a tie keeps the earlier surface).
        //   3) Return whether any surface was hit. Each surface fills out only when it is hit, so out
        //      ends up holding the closest hit.
        // BEGIN SOLUTION
        Ray closestSoFar = ray.copy();
        boolean hitAny = false;
        for (Surface surface : surfaces) {
            if (surface.intersect(out, closestSoFar)) {
                closestSoFar.end = out.t;
                hitAny = true;
            }
        }
        return hitAny;
        // END SOLUTION
        // STUB: return false;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[" + surfaces.size() + " surfaces]";
    }
}
