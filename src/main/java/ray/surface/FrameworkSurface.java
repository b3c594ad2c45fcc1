package ray.surface;

import java.util.List;
import java.util.Set;
import java.util.function.DoubleFunction;
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Acceleration;
import ray.accel.Hittable;
import ray.accel.SearchCounter;
import ray.math.Affine;
import ray.math.Bounds;
import ray.math.Vec3;
import ray.shading.Effect;

/**
 * What the framework asks of every surface besides its ray test: its parts, where it can be hit,
 * its copies (moved to the camera's frame, counted for a renderer thread), the facts the renderer
 * needs at a hit, and how the trace and the explore page name and draw it. {@link Surface}
 * implements it, so that the classes students open hold only their own data and the method they
 * write. Each default asks the facts of the surface's kind ({@link ShapeFacts#of}: a sphere's, a
 * triangle's, a cylinder's, a group's, or those of any surface); the framework's own surfaces (a
 * box, a mesh, a placed surface) override what they know better.
 */
public interface FrameworkSurface extends Hittable {
    /**
     * Whether the ray hits this surface for any t in (ray.start, ray.end): the question a shadow ray
     * asks, which any hit answers, so a search may stop at the first it finds. A surface made of
     * parts asks its parts; a primitive runs its intersect into a record nobody reads.
     */
    @Override
    default boolean intersectsAny(Ray ray) {
        return ShapeFacts.of(self()).intersectsAny(self(), ray);
    }

    /**
     * A box that holds every point where this surface can be hit, in the coordinates of whoever
     * holds it: its parts' boxes joined and mapped by {@link #childPlacement()}, or
     * {@link Bounds#EVERYTHING} for a primitive that does not say (so that it is never skipped).
     */
    @Override
    default Bounds bounds() {
        return ShapeFacts.of(self()).bounds(self());
    }

    /**
     * Called once every property is set (by the scene loader, or by code that builds a scene):
     * checks the surface and finishes building it.
     *
     * @return this surface
     * @throws IllegalArgumentException when the properties do not describe a valid surface
     */
    default Surface complete() {
        return ShapeFacts.of(self()).complete(self());
    }

    /** The surfaces this one is made of (empty for a primitive), for walking the scene tree. */
    default List<Surface> children() {
        return ShapeFacts.of(self()).children(self());
    }

    /**
     * Whether this is one primitive, tested by one call of its {@code intersect}: a surface without
     * parts that holds none by nature (a group, even an empty one, is no primitive).
     */
    default boolean isPrimitive() {
        return ShapeFacts.of(self()).isPrimitive(self());
    }

    /**
     * The copy of this surface that one renderer thread searches, counting every intersection test
     * and box test into {@code counter} where it happens, and searching as {@code acceleration}
     * says. It is hit where this surface is, and a hit names the same primitive.
     */
    default Surface searchCopy(Acceleration acceleration, SearchCounter counter) {
        return ShapeFacts.of(self()).searchCopy(self(), acceleration, counter);
    }

    /** The effects this surface itself calls for (a placed surface: transforms; a smooth triangle: vertex normals). */
    default Set<Effect> effects() {
        return ShapeFacts.of(self()).effects(self());
    }

    /** The map from the children's coordinates to this surface's: the identity but for a {@link Transformed}. */
    default Affine childPlacement() {
        return Affine.IDENTITY;
    }

    /**
     * What the renderer needs to start new rays at a hit on this primitive, made after the closest
     * hit is found (so {@code intersect} never computes it): see {@link HitGeometry}.
     *
     * @param hit a hit that intersect reported on this primitive, in its own coordinates
     */
    default HitGeometry hitGeometry(IntersectionRecord hit) {
        return ShapeFacts.of(self()).hitGeometry(self(), hit);
    }

    /**
     * This surface in coordinates whose origin is at {@code origin} of its own (every point p
     * becomes p − origin), for rendering from the camera's frame ({@code Scene#inCameraFrame}).
     */
    default Surface inFrameAt(Vec3 origin) {
        return ShapeFacts.of(self()).inFrameAt(self(), origin);
    }

    /**
     * A short name with the numbers that tell this surface apart, as {@code ray1 trace} and the
     * explore page show it, each number written by {@code number}: "Sphere center (0, 0, 0), radius
     * 1", "Group (3 surfaces)".
     */
    default String describe(DoubleFunction<String> number) {
        return ShapeFacts.of(self()).describe(self(), number);
    }

    /**
     * How {@code ray1 trace} names this surface's part {@code part}, number {@code index} from 0, in
     * a path ("triangle #8" in a mesh), or null when its parts are named by their own description.
     */
    default String partName(Surface part, int index) {
        return null;
    }

    /** Draws this surface for the explore page, mapped to the world by {@code toWorld}. */
    default void sketch(Sketch sketch, Affine toWorld) {
        ShapeFacts.of(self()).sketch(self(), sketch, toWorld);
    }

    /**
     * Why a hit this primitive reported (with a location and a normal) breaks what its shape
     * promises, for {@code ray1 trace} to flag, or null when nothing is seen to be wrong.
     */
    default String doubtAbout(IntersectionRecord hit, Ray ray) {
        return ShapeFacts.of(self()).doubtAbout(self(), hit, ray);
    }

    /** The kind of primitive this is, for naming what a pixel shows and whose task found it. */
    default SurfaceKind kind() {
        return ShapeFacts.of(self()).kind();
    }

    private Surface self() {
        return (Surface) this;
    }
}
