package ray;

import ray.math.Vec3;
import ray.surface.Surface;

/**
 * What a surface reports about a hit: where along the ray, where in space, the surface's
 * unit outward normal there, which surface was hit, (for triangles) the barycentric coordinates,
 * and the texture coordinates of the hit point.
 * Plain data, nothing else: copying these fields copies the hit.
 *
 * <p>A surface's {@code intersect} fills a record only when it reports a hit; on a miss the record
 * is left exactly as it was.
 */
public final class IntersectionRecord {
    /** The ray parameter of the hit: location = ray.origin + t·ray.direction. */
    public double t = Double.POSITIVE_INFINITY;
    public Vec3 location;
    /** Unit length, geometric-outward (never flipped toward the viewer). */
    public Vec3 normal;
    /** The primitive that was hit (a sphere or a triangle, never a group); its shader shades the hit. */
    public Surface surface;
    /** Barycentric coordinates of a triangle hit: location = (1 − beta − gamma)·v0 + beta·v1 + gamma·v2. */
    public double beta;
    public double gamma;
    /**
     * Texture coordinates (u, v) of the hit, where a texture is looked up: u across the image from
     * its left edge, v up from its bottom edge, one image per unit (see ray.shading.Texture).
     */
    public double texU;
    public double texV;

    /** Copies every field of {@code other} into this record. */
    public void set(IntersectionRecord other) {
        t = other.t;
        location = other.location;
        normal = other.normal;
        surface = other.surface;
        beta = other.beta;
        gamma = other.gamma;
        texU = other.texU;
        texV = other.texV;
    }

    @Override
    public String toString() {
        return "Hit[t " + t + ", at " + location + ", normal " + normal + ", surface " + surface + "]";
    }
}
