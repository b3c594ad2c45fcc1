package ray.surface;

import java.util.List;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;

/**
 * What the explore page draws of a scene (top and side views), in world coordinates. Each surface
 * sketches itself ({@link Surface#sketch}), so a new surface type is drawn, at least as its bounding
 * box, with no edit to the page's code.
 */
public interface Sketch {
    void sphere(Vec3 center, double radius);

    /** An upright cylinder: its axis is parallel to y, {@code height} long, centered on {@code center}. */
    void cylinder(Vec3 center, double radius, double height);

    /** An axis-aligned box. */
    void box(Vec3 min, Vec3 max);

    void triangle(Vec3 a, Vec3 b, Vec3 c);

    /** Triangles drawn as one shape (a mesh, a turned box), each mapped to the world by {@code toWorld}. */
    void mesh(List<? extends TriangleSurface> triangles, Affine toWorld);

    /** A surface's parts, each sketched and named in turn, in the coordinates {@code toWorld} maps from. */
    void parts(Surface whole, Affine toWorld);

    /** A shape with no drawing of its own, drawn as its world bounding box. */
    void bounds(Bounds world);
}
