package ray;

import ray.math.Vec3;
import ray.surface.HitGeometry;
import ray.surface.Surface;

/**
 * What a surface reports about a hit: where along the ray, where in space, the surface's
 * unit outward normal there, which surface was hit and (for triangles) the barycentric coordinates.
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

    // Framework-owned (a surface's intersect never touches these): see geometry().
    private HitGeometry geometry;
    /** The location object that {@link #geometry} describes; a surface reporting a new hit replaces location. */
    private Vec3 geometryLocation;

    public void set(IntersectionRecord other) {
        t = other.t;
        location = other.location;
        normal = other.normal;
        surface = other.surface;
        beta = other.beta;
        gamma = other.gamma;
        geometry = other.geometry;
        geometryLocation = other.geometryLocation;
    }

    /**
     * The hit's geometry for starting new rays from it (used by the renderer, not by surfaces):
     * the one that {@link ray.surface.Transformed} carried out of a transformed group, or else
     * made now from location and surface, which are then in the coordinates of the caller.
     * A surface that reports a hit after that replaces location, so a geometry kept from an
     * earlier, farther hit is never taken for the new one.
     */
    public HitGeometry geometry() {
        if (geometry == null || geometryLocation != location) {
            setGeometry(HitGeometry.of(this));
        }
        return geometry;
    }

    /** Records {@code g} as the geometry of the hit now in this record (for {@link ray.surface.Transformed}). */
    public void setGeometry(HitGeometry g) {
        geometry = g;
        geometryLocation = location;
    }

    @Override
    public String toString() {
        return "Hit[t " + t + ", at " + location + ", normal " + normal + ", surface " + surface + "]";
    }
}
