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
import ray.shading.Shader;

/**
 * Anything a ray can hit.
 *
 * <p>The contract every surface keeps: {@link #intersect} returns true only for a hit with
 * ray.start &lt; t &lt; ray.end, and then fills the record (t, location, unit outward normal,
 * the primitive that was hit); on a miss it leaves the record untouched.
 */
public abstract class Surface implements Hittable, Cloneable {
    private Shader shader;

    /**
     * Intersects the ray with this surface.
     *
     * @param out filled with the hit when there is one, untouched otherwise
     * @param ray the segment to test; only read, never changed
     * @return whether the ray hits this surface for some t in (ray.start, ray.end)
     */
    public abstract boolean intersect(IntersectionRecord out, Ray ray);

    /**
     * Whether the ray hits this surface for any t in (ray.start, ray.end): the question a shadow ray
     * asks, which any hit answers, so a search may stop at the first it finds. A surface made of
     * parts asks its parts (a {@link Group}'s, whatever order its own loop takes: any hit is as good
     * as the closest); a primitive runs its {@link #intersect} into a record nobody reads.
     */
    public boolean intersectsAny(Ray ray) {
        List<Surface> parts = children();
        if (parts.isEmpty()) {
            return intersect(new IntersectionRecord(), ray);
        }
        for (Surface part : parts) {
            if (part.intersectsAny(ray)) {
                return true;
            }
        }
        return false;
    }

    /**
     * A box that holds every point where this surface can be hit, in the coordinates of whoever
     * holds it: its parts' boxes joined and mapped by {@link #childPlacement()}, or
     * {@link Bounds#EVERYTHING} for a primitive that does not say (so that it is never skipped; the
     * framework's spheres, triangles and cylinders say).
     * Computed when asked; a surface that tests it per ray keeps it.
     */
    public Bounds bounds() {
        List<Surface> parts = children();
        if (parts.isEmpty()) {
            // A primitive that does not say where it can be hit may be hit anywhere (an empty group says nothing can).
            return Bounds.EVERYTHING;
        }
        Bounds box = Bounds.EMPTY;
        for (Surface part : parts) {
            box = box.union(part.bounds());
        }
        return box.transformed(childPlacement());
    }

    /** This surface's shader; null until the scene gives it one (a surface without one takes its group's). */
    public Shader getShader() {
        return shader;
    }

    public void setShader(Shader shader) {
        this.shader = shader;
    }

    /**
     * Called once every property is set (by the scene loader, or by code that builds a scene):
     * checks the surface and finishes building it.
     *
     * @return this surface
     * @throws IllegalArgumentException when the properties do not describe a valid surface
     */
    public Surface complete() {
        return this;
    }

    /** The surfaces this one is made of (empty for a primitive), for walking the scene tree. */
    public List<Surface> children() {
        return List.of();
    }

    /**
     * Whether this is one primitive, tested by one call of its {@code intersect}: a surface without
     * parts that holds none by nature (a group, even an empty one, is no primitive).
     */
    public boolean isPrimitive() {
        return children().isEmpty();
    }

    /**
     * The copy of this surface that one renderer thread searches, counting every intersection test
     * and box test into {@code counter} where it happens, and searching as {@code acceleration}
     * says. It is hit where this surface is, and a hit names the same primitive (the primitive
     * fills the record). This default counts one test per search: a primitive, or any surface not
     * known to be made of parts.
     */
    public Surface searchCopy(Acceleration acceleration, SearchCounter counter) {
        return new CountedCopy.OneTest(this, counter);
    }

    /** The effects this surface itself calls for (a placed surface: transforms; a smooth triangle: vertex normals). */
    public Set<Effect> effects() {
        return Set.of();
    }

    /** The map from the children's coordinates to this surface's: the identity but for a {@link Transformed}. */
    public Affine childPlacement() {
        return Affine.IDENTITY;
    }

    /**
     * What the renderer needs to start new rays at a hit on this primitive, made after the closest
     * hit is found (so {@code intersect} never computes it): see {@link HitGeometry}. A primitive
     * with more exact knowledge of its own shape (a sphere, a triangle) overrides this.
     *
     * @param hit a hit that {@link #intersect} reported on this primitive, in its own coordinates
     */
    public HitGeometry hitGeometry(IntersectionRecord hit) {
        return HitGeometry.atReportedPoint(hit);
    }

    /**
     * This surface in coordinates whose origin is at {@code origin} of its own (every point p
     * becomes p − origin), for rendering from the camera's frame ({@code Scene#inCameraFrame}).
     * The framework's surfaces move their own numbers, subtracting once in double, so that rays
     * from the camera meet numbers of the scene's size rather than of its distance from the origin;
     * any other surface is placed by a translation, which is exact in meaning though not in accuracy.
     */
    public Surface inFrameAt(Vec3 origin) {
        return new Transformed(this, Affine.translation(origin.negate()));
    }

    /** A shallow copy of this surface (same class, same fields), for {@link #inFrameAt} to change. */
    protected final Surface copy() {
        try {
            return (Surface) clone();
        } catch (CloneNotSupportedException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * A short name with the numbers that tell this surface apart, as {@code ray1 trace} and the
     * explore page show it, each number written by {@code number}: "Sphere center (0, 0, 0), radius
     * 1", "Group (3 surfaces)". A surface with parts names their count; any other its toString.
     */
    public String describe(DoubleFunction<String> number) {
        int parts = children().size();
        return parts == 0 ? toString() : namedClass() + " (" + count(parts, "surface") + ")";
    }

    /**
     * How {@code ray1 trace} names this surface's part {@code part}, number {@code index} from 0, in
     * a path ("triangle #8" in a mesh), or null when its parts are named by their own description
     * (a group's surfaces).
     */
    public String partName(Surface part, int index) {
        return null;
    }

    /**
     * Draws this surface for the explore page, mapped to the world by {@code toWorld}: its parts one
     * by one, or, for a primitive that draws nothing of its own, its bounding box.
     */
    public void sketch(Sketch sketch, Affine toWorld) {
        if (children().isEmpty()) {
            sketch.bounds(bounds().transformed(toWorld));
        } else {
            sketch.parts(this, toWorld.after(childPlacement()));
        }
    }

    /** "(x, y, z)", each coordinate written by {@code number}. */
    protected static String vec(Vec3 p, DoubleFunction<String> number) {
        return p == null ? "null" : p.format(number);
    }

    /** "12 triangles", "1 surface". */
    protected static String count(int n, String noun) {
        return n + " " + noun + (n == 1 ? "" : "s");
    }

    /**
     * Why a hit this primitive reported (with a location and a normal) breaks what its shape
     * promises, for {@code ray1 trace} to flag, or null when nothing is seen to be wrong. A shape
     * that knows its inside says so (a sphere: the far root).
     */
    public String doubtAbout(IntersectionRecord hit, Ray ray) {
        return null;
    }

    /**
     * The kind of primitive this is, for naming what a pixel shows and whose task found it: the
     * framework's shapes say theirs; any other surface is {@link SurfaceKind#OTHER}.
     */
    public SurfaceKind kind() {
        return SurfaceKind.OTHER;
    }

    /** The simple name of this surface's class, or of the named class an anonymous one extends ("Group"). */
    private String namedClass() {
        Class<?> named = getClass();
        while (named.isAnonymousClass()) {
            named = named.getSuperclass();
        }
        return named.getSimpleName();
    }

    @Override
    public String toString() {
        return namedClass();
    }
}
