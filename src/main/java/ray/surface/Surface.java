package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.shading.Shader;

/**
 * Anything a ray can hit.
 *
 * <p>The contract every surface keeps: {@link #intersect} returns true only for a hit with
 * ray.start &lt; t &lt; ray.end, and then fills the record (t, location, unit outward normal,
 * the primitive that was hit); on a miss it leaves the record untouched.
 *
 * <p>What the framework asks of a surface besides (its parts, bounds, copies, names) is in
 * {@link FrameworkSurface}; none of it is needed to write an intersect.
 */
public abstract class Surface implements FrameworkSurface, Cloneable {
    private Shader shader;

    /**
     * Intersects the ray with this surface.
     *
     * @param out filled with the hit when there is one, untouched otherwise
     * @param ray the segment to test; only read, never changed
     * @return whether the ray hits this surface for some t in (ray.start, ray.end)
     */
    @Override
    public abstract boolean intersect(IntersectionRecord out, Ray ray);

    /** This surface's shader; null until the scene gives it one (a surface without one takes its group's). */
    public Shader getShader() {
        return shader;
    }

    public void setShader(Shader shader) {
        this.shader = shader;
    }

    /** A shallow copy (same class, same fields), for the framework to move ({@link ShapeFacts#inFrameAt}). */
    final Surface shallowCopy() {
        try {
            return (Surface) clone();
        } catch (CloneNotSupportedException e) {
            throw new IllegalStateException(e);
        }
    }

    @Override
    public String toString() {
        return ShapeFacts.of(this).name(this);
    }
}
