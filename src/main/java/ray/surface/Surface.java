package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.shading.Shader;

/**
 * Anything a ray can hit.
 *
 * <p>The contract every surface keeps: {@link #intersect} returns true only for a hit with
 * ray.start &lt; t &lt; ray.end, and then fills the record (t, location, unit outward normal,
 * the primitive that was hit); on a miss it leaves the record untouched.
 */
public abstract class Surface {
    private Shader shader;

    /**
     * Intersects the ray with this surface.
     *
     * @param out filled with the hit when there is one, untouched otherwise
     * @param ray the segment to test; only read, never changed
     * @return whether the ray hits this surface for some t in (ray.start, ray.end)
     */
    public abstract boolean intersect(IntersectionRecord out, Ray ray);

    public Shader getShader() {
        return shader;
    }

    public void setShader(Shader shader) {
        this.shader = shader;
    }

    /** Gives this surface {@code inherited} if it has no shader of its own; groups pass it on to their children. */
    public void inheritShader(Shader inherited) {
        if (shader == null) {
            shader = inherited;
        }
    }

    /**
     * Called once every property is set (by the scene loader, or by code that builds a scene):
     * checks the surface and finishes building it.
     *
     * @return the surface to place in the scene: this one, or a wrapper around it (a transformed group)
     * @throws IllegalArgumentException when the properties do not describe a valid surface
     */
    public Surface complete() {
        return this;
    }

    /** The surfaces this one is made of (empty for a primitive), for walking the scene tree. */
    public List<Surface> children() {
        return List.of();
    }

    @Override
    public String toString() {
        return getClass().getSimpleName();
    }
}
