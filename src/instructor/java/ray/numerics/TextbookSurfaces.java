package ray.numerics;

import java.util.List;
import java.util.function.Function;
import ray.IntersectionRecord;
import ray.Ray;
import ray.math.Affine;
import ray.surface.Group;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Transformed;
import ray.surface.Triangle;

/**
 * Scenes whose spheres or triangles intersect by a textbook method ({@link TextbookSphere},
 * {@link TextbookTriangles}) instead of the solution's, for the figures and the tolerance survey.
 * Each is a {@link StandIn}: the original shader shades its hits and the framework makes their
 * offsets from the original primitive's own numbers.
 */
public final class TextbookSurfaces {
    private TextbookSurfaces() {
    }

    /** A copy of the surface tree whose triangles intersect by {@code method}; groups and transforms kept. */
    public static Surface withTriangles(Surface surface, TextbookTriangles.Method method) {
        return replaceLeaves(surface, leaf -> leaf instanceof Triangle ? triangle((Triangle) leaf, method) : leaf);
    }

    /** A copy of the surface tree whose spheres intersect by the textbook formula ({@link TextbookSphere}). */
    public static Surface withTextbookSpheres(Surface surface) {
        return replaceLeaves(surface, leaf -> leaf instanceof Sphere ? sphere((Sphere) leaf) : leaf);
    }

    /** {@code triangle} tested by {@code method}; the hit names the triangle, so its shader and offsets apply. */
    public static Surface triangle(Triangle triangle, TextbookTriangles.Method method) {
        return new TriangleBy(triangle, method);
    }

    /** {@code sphere} tested by the textbook formula; the hit names the sphere, so its shader and offsets apply. */
    public static Surface sphere(Sphere sphere) {
        return new TextbookSphereOf(sphere);
    }

    /**
     * A copy of the tree with {@code leaf} applied to every primitive. A surface made of parts (a
     * group, a box's or a mesh's triangles, a placement's one surface) becomes its parts, replaced,
     * in a plain group (so a mesh is searched by a linear loop here, which changes the time, not the
     * image), placed as the surface placed them.
     */
    static Surface replaceLeaves(Surface surface, Function<Surface, Surface> leaf) {
        List<Surface> parts = surface.children();
        if (parts.isEmpty()) {
            return leaf.apply(surface);
        }
        Group copy = new Group();
        for (Surface part : parts) {
            copy.addSurface(replaceLeaves(part, leaf));
        }
        Affine placement = surface.childPlacement();
        return placement.isIdentity() ? copy : new Transformed(copy, placement);
    }

    /** A triangle tested by another method; the hit names the triangle itself, so its shader and offsets apply. */
    private static final class TriangleBy extends StandIn {
        private final Triangle triangle;
        private final TextbookTriangles.Method method;

        TriangleBy(Triangle triangle, TextbookTriangles.Method method) {
            super(triangle);
            this.triangle = triangle;
            this.method = method;
        }

        @Override
        protected boolean test(IntersectionRecord out, Ray ray) {
            return method.intersect(triangle, out, ray);
        }
    }

    /**
     * A sphere tested by the textbook formula (t, location and normal as a student's first Task 2
     * gives them); the hit names the sphere itself, so that its shader applies and the framework makes
     * its offsets from the sphere's own numbers, as it does for a student's code.
     */
    private static final class TextbookSphereOf extends StandIn {
        private final TextbookSphere textbook;

        TextbookSphereOf(Sphere sphere) {
            super(sphere);
            this.textbook = new TextbookSphere(sphere.getCenter(), sphere.getRadius());
        }

        @Override
        protected boolean test(IntersectionRecord out, Ray ray) {
            return textbook.intersect(out, ray);
        }
    }
}
